// The exposure slider of the job's image: stops from -5 to +5 in half stops. Until it is
// moved the image is the render's own (no exposure in the request: the server's cached PNG,
// at the scene's render.exposure); once moved, the image is asked for at that exposure
// (GET /jobs/{id}/image?exposure=E) and Reset goes back to the render's.
//
// createExposureControl({ slider, label, reset, onChange }):
//   onChange(exposure)   exposure in stops, or null for the render's own.
// Returns { value(), setRenderExposure(stops|null), clear() }.

export function formatStops(stops) {
  const sign = stops > 0 ? '+' : stops < 0 ? '−' : '±';
  return `${sign}${Math.abs(stops)} EV`;
}

export function createExposureControl({ slider, label, reset, onChange }) {
  let chosen = null; // stops, or null: the render's own
  let renderExposure = null; // the scene's render.exposure when known

  function show() {
    if (chosen !== null) {
      label.textContent = formatStops(chosen);
    } else {
      label.textContent = renderExposure === null ? "the render's" : `${formatStops(renderExposure)} (render's)`;
    }
    reset.disabled = chosen === null;
  }

  // The thumb rests at the render's exposure (to the nearest half stop) while none is chosen.
  function placeThumb() {
    const at = chosen ?? renderExposure ?? 0;
    slider.value = String(Math.min(5, Math.max(-5, Math.round(at * 2) / 2)));
  }

  slider.addEventListener('input', () => {
    const stops = Number(slider.value);
    if (stops === chosen) return;
    chosen = stops;
    show();
    onChange(chosen);
  });
  reset.addEventListener('click', () => {
    if (chosen === null) return;
    chosen = null;
    placeThumb();
    show();
    onChange(null);
  });

  return {
    value: () => chosen,
    setRenderExposure(stops) {
      renderExposure = typeof stops === 'number' && Number.isFinite(stops) ? stops : null;
      if (chosen === null) placeThumb();
      show();
    },
    // Another job: its own exposure until the slider is moved (no onChange).
    clear() {
      chosen = null;
      renderExposure = null;
      placeThumb();
      show();
    },
  };
}
