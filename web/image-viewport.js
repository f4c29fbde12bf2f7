// Zoom and pan of the job's image inside a fixed frame (the viewport): mouse wheel around the
// cursor, buttons and keys in steps of √2, drag to pan, pinch with two fingers, "Fit" (the
// whole image in the frame) and "1:1" (one image pixel per device pixel: on a screen of
// devicePixelRatio 2 that is half a CSS pixel, so the render is shown without resampling). Every image of the view (the job's,
// and the one it is compared with) gets the same transform, so they stay aligned.
//
// The transform lives here, not on the <img>'s source: a new pass (the preview loader sets a
// new src of the same size) keeps the zoom; only an image of another size refits.
//
// createImageViewport({ frame, images, zoomLabel }):
//   frame       the element that clips (overflow: hidden); its size is the view.
//   images      the <img> elements to transform alike (position: absolute at 0,0).
//   zoomLabel   an element that shows the zoom in percent of 1:1.
// Returns { setImageSize(w, h), clear(), fit(), oneToOne(), zoomIn(), zoomOut(), zoomAt(factor, x, y),
//   panBy(dx, dy), state() }.

// One wheel notch of a mouse (deltaY 100 CSS px) zooms by √2, like the buttons.
const WHEEL_PX_PER_DOUBLING = 200;
const KEY_PAN_PX = 40;
// Zoom limits: down to half the smaller of Fit and 1:1, up to 32 device pixels per image pixel.
const MAX_DEVICE_SCALE = 32;
// From 2 device pixels per image pixel on, pixels are drawn as squares; below, squares of
// uneven sizes (1 or 2 pixels wide) would look worse than a smooth resampling.
const PIXELATED_FROM = 2;

export const ZOOM_STEP = Math.SQRT2;

export function createImageViewport({ frame, images, zoomLabel }) {
  let width = 0; // the image's size in image pixels (0: none yet)
  let height = 0;
  let scale = 1; // CSS px per image pixel
  let x = 0; // the image's top-left corner in the frame, CSS px
  let y = 0;
  let mode = 'fit'; // 'fit' follows the frame's size; 'free' after any zoom or pan

  const dpr = () => window.devicePixelRatio || 1;
  const frameSize = () => ({ w: frame.clientWidth, h: frame.clientHeight });
  // Corners on the device pixel grid, so that at 1:1 (and any whole magnification) each image
  // pixel lands on whole device pixels and stays sharp.
  const snap = (v) => Math.round(v * dpr()) / dpr();

  function fitScale() {
    const { w, h } = frameSize();
    return width && height && w && h ? Math.min(w / width, h / height) : 1;
  }

  function limits() {
    return { min: Math.min(fitScale(), 1 / dpr()) / 2, max: MAX_DEVICE_SCALE / dpr() };
  }

  // Along one axis: an image smaller than the frame stays wholly inside it; a larger one
  // keeps covering it (no empty band on the side it was dragged away from).
  function clampAxis(offset, size, room) {
    const lo = Math.min(0, room - size);
    const hi = Math.max(0, room - size);
    return Math.min(hi, Math.max(lo, offset));
  }

  function apply() {
    const { w, h } = frameSize();
    x = clampAxis(x, width * scale, w);
    y = clampAxis(y, height * scale, h);
    // Only what is drawn is snapped: x and y stay exact, so steps of zoom never drift.
    const [left, top] = [snap(x), snap(y)];
    for (const img of images) {
      img.style.width = `${width}px`;
      img.style.height = `${height}px`;
      img.style.transform = `translate(${left}px, ${top}px) scale(${scale})`;
    }
    // Magnified enough that image pixels are seen: each a sharp square, not a blur.
    frame.classList.toggle('magnified', scale * dpr() >= PIXELATED_FROM);
    frame.dataset.scale = String(scale);
    frame.dataset.x = String(x);
    frame.dataset.y = String(y);
    frame.dataset.mode = mode;
    if (zoomLabel) zoomLabel.textContent = `${Math.round(scale * dpr() * 100)}%`;
  }

  function fit() {
    if (!width) return;
    const { w, h } = frameSize();
    mode = 'fit';
    scale = fitScale();
    x = (w - width * scale) / 2;
    y = (h - height * scale) / 2;
    apply();
  }

  // Zoom to `next` (CSS px per image pixel) keeping the image point under (px, py) in place.
  function zoomTo(next, px, py) {
    if (!width) return;
    const { min, max } = limits();
    const clamped = Math.min(max, Math.max(min, next));
    const u = (px - x) / scale;
    const v = (py - y) / scale;
    mode = 'free';
    scale = clamped;
    x = px - u * scale;
    y = py - v * scale;
    apply();
  }

  function center() {
    const { w, h } = frameSize();
    return [w / 2, h / 2];
  }

  function oneToOne() {
    zoomTo(1 / dpr(), ...center());
  }

  // Buttons and keys go through the levels 2^(k/2) device pixels per image pixel, so that
  // from any zoom they reach 1:1, 2:1, 4:1 exactly.
  function stepLevel(direction) {
    const level = Math.log2(scale * dpr()) * 2;
    const k = direction > 0 ? Math.floor(level + 1e-9) + 1 : Math.ceil(level - 1e-9) - 1;
    zoomTo(2 ** (k / 2) / dpr(), ...center());
  }

  function panBy(dx, dy) {
    if (!width) return;
    mode = 'free';
    x += dx;
    y += dy;
    apply();
  }

  // A pointer's place in the frame's content box (the image's coordinates start inside the border).
  function inFrame(event) {
    const rect = frame.getBoundingClientRect();
    return [event.clientX - rect.left - frame.clientLeft, event.clientY - rect.top - frame.clientTop];
  }

  frame.addEventListener('wheel', (event) => {
    if (!width) return;
    event.preventDefault();
    const unit = event.deltaMode === 1 ? 16 : event.deltaMode === 2 ? frame.clientHeight : 1;
    zoomTo(scale * 2 ** (-(event.deltaY * unit) / WHEEL_PX_PER_DOUBLING), ...inFrame(event));
  }, { passive: false });

  // The pointers down on the image, by id: their last place in the frame. One drags the
  // image; two (fingers on a touch screen) also pinch: the zoom follows their distance
  // around their midpoint, and the midpoint's travel pans.
  const pointers = new Map();
  const midpoint = () => {
    const [a, b] = [...pointers.values()];
    return { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2, d: Math.hypot(a.x - b.x, a.y - b.y) };
  };
  frame.addEventListener('pointerdown', (event) => {
    if (!width || event.button !== 0 || event.target.closest('[data-no-pan]') || pointers.size >= 2) return;
    event.preventDefault(); // no image drag-and-drop, no text selection
    const [px, py] = inFrame(event);
    pointers.set(event.pointerId, { x: px, y: py });
    try {
      frame.setPointerCapture(event.pointerId); // moves outside the frame still drag
    } catch {
      // A pointer the browser no longer tracks: it drags while over the frame.
    }
    frame.classList.add('dragging');
    frame.focus({ preventScroll: true });
  });
  frame.addEventListener('pointermove', (event) => {
    const last = pointers.get(event.pointerId);
    if (!last) return;
    const [px, py] = inFrame(event);
    if (pointers.size === 1) {
      pointers.set(event.pointerId, { x: px, y: py });
      panBy(px - last.x, py - last.y);
      return;
    }
    const before = midpoint();
    pointers.set(event.pointerId, { x: px, y: py });
    const after = midpoint();
    if (before.d > 0 && after.d > 0) zoomTo(scale * (after.d / before.d), before.x, before.y);
    panBy(after.x - before.x, after.y - before.y);
  });
  const endDrag = (event) => {
    if (!pointers.delete(event.pointerId)) return;
    if (pointers.size === 0) frame.classList.remove('dragging');
  };
  frame.addEventListener('pointerup', endDrag);
  frame.addEventListener('pointercancel', endDrag);
  // Double click: from Fit to 1:1 at that point, from any other zoom back to Fit.
  frame.addEventListener('dblclick', (event) => {
    if (!width || event.target.closest('[data-no-pan]')) return;
    if (mode === 'fit') {
      zoomTo(1 / dpr(), ...inFrame(event));
    } else {
      fit();
    }
  });

  const KEYS = {
    '+': () => stepLevel(1),
    '=': () => stepLevel(1),
    '-': () => stepLevel(-1),
    _: () => stepLevel(-1),
    0: fit,
    1: oneToOne,
    ArrowLeft: () => panBy(KEY_PAN_PX, 0),
    ArrowRight: () => panBy(-KEY_PAN_PX, 0),
    ArrowUp: () => panBy(0, KEY_PAN_PX),
    ArrowDown: () => panBy(0, -KEY_PAN_PX),
  };
  frame.addEventListener('keydown', (event) => {
    const action = KEYS[event.key];
    if (!action || event.ctrlKey || event.metaKey || event.altKey || !width) return;
    event.preventDefault();
    action();
  });

  // Fit follows the frame (a resized window, the phone layout); a chosen zoom stays.
  new ResizeObserver(() => (mode === 'fit' ? fit() : apply())).observe(frame);

  return {
    // A new image size refits; the same size (the next pass, another exposure) keeps the view.
    setImageSize(w, h) {
      if (w === width && h === height) return;
      width = w;
      height = h;
      // The frame takes the image's shape (up to its max-height), so Fit leaves no bands.
      frame.style.aspectRatio = `${w} / ${h}`;
      fit();
    },
    // Another job: its first image is fitted, whatever its size.
    clear() {
      width = 0;
      height = 0;
      mode = 'fit';
    },
    fit,
    oneToOne,
    zoomIn: () => stepLevel(1),
    zoomOut: () => stepLevel(-1),
    zoomAt: zoomTo,
    panBy,
    state: () => ({ scale, x, y, mode, width, height }),
  };
}
