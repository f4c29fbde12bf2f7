// The job view's live preview, made for slow links: at most one image on its way at a time,
// decoded off-screen before it replaces the one on show, so a partial image is never shown
// and a load is never aborted by the next pass. Passes that finish while an image loads are
// skipped: when it has arrived, the newest pass is asked for next, and the last pass asked
// for (the job's final one) is always loaded in the end.
//
// createPreviewLoader({ img, load, onShown, onError }):
//   load(pass)    -> Promise<{ blob, pass }>, the image after `pass` (api.js fetchImage);
//                    its pass may be older than asked while the server catches up.
//   onShown(pass)    after the <img> shows that pass.
//   onError(error)   a load failed; the next want() tries again.
// Returns { want(pass), reload(), stop(), shownPass() }.
//
// reload(): the image's settings changed (exposure, layer: load() reads them when called), so
// the pass on show is loaded once more, the same way (off-screen, then swapped). An image
// that was already on its way with the old settings is not shown.

// The server encodes a running job's image at most every 250 ms and answers with the last
// one in between: wait that long before asking again for a pass it did not have yet.
const LAGGING_RETRY_MS = 300;
// A pass that never comes (the job stopped short of it) is given up after this many tries.
const MAX_LAGGING_TRIES = 20;

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

export function createPreviewLoader({ img, load, onShown = () => {}, onError = () => {} }) {
  let wanted = 0; // the newest pass asked for
  let shown = 0; // the pass on show
  let settings = 0; // counts reload()s: the settings load() uses now
  let shownSettings = 0; // the settings of the image on show
  let shownUrl = null; // its blob: URL, revoked when replaced
  let running = false;
  let stopped = false;

  // Decodes the image away from the page; resolves to its blob: URL, or throws.
  async function decode(blob) {
    const url = URL.createObjectURL(blob);
    try {
      const offscreen = new Image();
      offscreen.src = url;
      await offscreen.decode();
      return url;
    } catch (error) {
      URL.revokeObjectURL(url);
      throw error;
    }
  }

  function swap(url, pass, made) {
    if (shownUrl) URL.revokeObjectURL(shownUrl);
    shownUrl = url;
    shown = pass;
    shownSettings = made;
    // The pass first, so whoever watches src sees which pass it is.
    img.dataset.pass = String(pass);
    img.src = url;
    onShown(pass);
  }

  // A newer pass to show, or the one on show with settings since changed.
  const behind = () => wanted > shown || (wanted > 0 && shownSettings < settings);

  async function run() {
    running = true;
    let lagging = 0;
    try {
      while (!stopped && behind() && lagging < MAX_LAGGING_TRIES) {
        const asked = wanted;
        const made = settings;
        const answer = await load(asked);
        if (stopped) return;
        if (made !== settings) continue; // settings changed on the way: ask again with them
        const pass = answer.pass ?? asked;
        if (pass > shown || (pass === shown && shownSettings < made)) {
          const url = await decode(answer.blob);
          if (stopped || made !== settings) {
            URL.revokeObjectURL(url);
            if (stopped) return;
            continue;
          }
          swap(url, pass, made);
        }
        if (pass < asked) {
          lagging++;
          await sleep(LAGGING_RETRY_MS);
        } else {
          lagging = 0;
        }
      }
    } catch (error) {
      if (!stopped) onError(error);
    } finally {
      running = false;
    }
  }

  return {
    // Also after a failed load: asking again for the same pass tries again.
    want(pass) {
      if (stopped) return;
      if (pass > wanted) wanted = pass;
      if (!running && behind()) run();
    },
    reload() {
      if (stopped) return;
      settings++;
      if (!running && behind()) run();
    },
    stop() {
      stopped = true;
      if (shownUrl) URL.revokeObjectURL(shownUrl);
      shownUrl = null;
    },
    shownPass: () => shown,
  };
}
