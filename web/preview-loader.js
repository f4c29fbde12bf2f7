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
// Returns { want(pass), stop(), shownPass() }.

// The server encodes a running job's image at most every 250 ms and answers with the last
// one in between: wait that long before asking again for a pass it did not have yet.
const LAGGING_RETRY_MS = 300;
// A pass that never comes (the job stopped short of it) is given up after this many tries.
const MAX_LAGGING_TRIES = 20;

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

export function createPreviewLoader({ img, load, onShown = () => {}, onError = () => {} }) {
  let wanted = 0; // the newest pass asked for
  let shown = 0; // the pass on show
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

  function swap(url, pass) {
    if (shownUrl) URL.revokeObjectURL(shownUrl);
    shownUrl = url;
    shown = pass;
    // The pass first, so whoever watches src sees which pass it is.
    img.dataset.pass = String(pass);
    img.src = url;
    onShown(pass);
  }

  async function run() {
    running = true;
    let lagging = 0;
    try {
      while (!stopped && wanted > shown && lagging < MAX_LAGGING_TRIES) {
        const asked = wanted;
        const answer = await load(asked);
        if (stopped) return;
        const pass = answer.pass ?? asked;
        if (pass > shown) {
          const url = await decode(answer.blob);
          if (stopped) return URL.revokeObjectURL(url);
          swap(url, pass);
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
      if (!running && wanted > shown) run();
    },
    stop() {
      stopped = true;
      if (shownUrl) URL.revokeObjectURL(shownUrl);
      shownUrl = null;
    },
    shownPass: () => shown,
  };
}
