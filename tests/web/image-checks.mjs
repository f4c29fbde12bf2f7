// What the page test (page.test.mjs) reads of the job's image: the zoom and pan of the view,
// the compare view's divider and clip, and the pixels shown against the server's. Each
// takes the Playwright page.

// The view as the viewport keeps it (scale, the image's exact corner x, y in the frame) and as
// it is drawn: the transform's translation (the corner on the device pixel grid) and where
// the image really is on the page, relative to the frame's inside, in CSS px.
export async function imageView(page) {
  return page.evaluate(() => {
    const frame = document.querySelector('#image-frame');
    const img = document.querySelector('#job-image');
    const f = frame.getBoundingClientRect();
    const r = img.getBoundingClientRect();
    const [, left, top] = /^translate\((-?[\d.]+)px, (-?[\d.]+)px\)/.exec(img.style.transform).map(Number);
    return {
      scale: Number(frame.dataset.scale), x: Number(frame.dataset.x), y: Number(frame.dataset.y), mode: frame.dataset.mode,
      drawn: [left, top], box: [r.left - f.left - frame.clientLeft, r.top - f.top - frame.clientTop, r.width, r.height],
      frame: [frame.clientWidth, frame.clientHeight], pixelated: getComputedStyle(img).imageRendering === 'pixelated',
      zoom: document.querySelector('#zoom-level').textContent,
    };
  });
}

// What the viewport must show for scale s and exact corner (x, y), on a screen of ratio dpr.
export function expectedView(scale, x, y, dpr = 1) {
  const snap = (v) => Math.round(v * dpr) / dpr;
  return { scale, x, y, drawn: [snap(x), snap(y)] };
}

export const viewOf = ({ scale, x, y, drawn }) => ({ scale, x, y, drawn });

// The pixels of the image on show and of the server's PNG at `query`, decoded alike by the
// browser: { shown, served } as arrays of R, G, B (alpha left out). The request for the PNG
// is the test's: it is marked, so it is not taken for one of the page's.
export async function shownAndServedPixels(page, id, query) {
  return page.evaluate(async ({ jobId, q }) => {
    const rgb = (source, width, height) => {
      const canvas = document.createElement('canvas');
      canvas.width = width;
      canvas.height = height;
      const context = canvas.getContext('2d');
      context.drawImage(source, 0, 0);
      return Array.from(context.getImageData(0, 0, width, height).data).filter((_, i) => i % 4 !== 3);
    };
    const img = document.querySelector('#job-image');
    const res = await fetch(`/api/v1/jobs/${jobId}/image${q}`, { headers: { 'X-Test-Check': '1' } });
    const bitmap = await createImageBitmap(await res.blob());
    return { shown: rgb(img, img.naturalWidth, img.naturalHeight), served: rgb(bitmap, bitmap.width, bitmap.height) };
  }, { jobId: id, q: query });
}

// An sRGB-encoded 8-bit value in linear light.
export const linear = (v) => {
  const c = v / 255;
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
};

// The compare view's state: what is chosen, the divider, the clip, both images' transforms.
export async function compareState(page) {
  return page.evaluate(() => {
    const frame = document.querySelector('#image-frame');
    const divider = document.querySelector('#compare-divider');
    const other = document.querySelector('#compare-image');
    // inset(top right bottom left), as the browser shortens it ("inset(0px)" when all are 0):
    // the clip's sides in CSS px, in full.
    const sides = /^inset\((.*)\)$/.exec(document.querySelector('#compare-layer').style.clipPath)[1].split(' ').map((v) => Number.parseFloat(v));
    const [top, right = top, bottom = top, left = right] = sides;
    return {
      choice: document.querySelector('#compare-select').value, hidden: divider.hidden,
      split: Number(divider.dataset.split), valuenow: divider.getAttribute('aria-valuenow'),
      clip: [top, right, bottom, left], left: divider.style.left, width: frame.clientWidth,
      sameTransform: other.style.transform === document.querySelector('#job-image').style.transform,
      other: { job: other.dataset.job, pass: other.dataset.pass, width: other.naturalWidth },
      labels: [document.querySelector('#compare-left-label').textContent, document.querySelector('#compare-right-label').textContent],
    };
  });
}
