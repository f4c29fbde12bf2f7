// Keeps a form's contents across reloads (localStorage): the listed inputs, selects and
// textareas, saved as they are edited and put back when the page loads. Files cannot be
// kept (a browser does not let a page set a file input), so file inputs are never listed.

const SAVE_MS = 300; // edits closer together than this are saved once

// Puts the saved values back and saves every later edit. Returns { forget() }.
export function rememberForm(form, ids, key) {
  const fields = ids.map((id) => document.getElementById(id)).filter(Boolean);

  function read() {
    try {
      return JSON.parse(localStorage.getItem(key) || '{}') || {};
    } catch {
      return {};
    }
  }

  const saved = read();
  for (const field of fields) {
    if (!(field.id in saved)) continue;
    if (field.type === 'checkbox') field.checked = saved[field.id] === true;
    else field.value = String(saved[field.id]);
  }

  let timer = null;
  function save() {
    clearTimeout(timer);
    timer = null;
    const values = {};
    for (const field of fields) values[field.id] = field.type === 'checkbox' ? field.checked : field.value;
    try {
      localStorage.setItem(key, JSON.stringify(values));
    } catch {
      // Storage full or refused (private mode): the form is simply not kept.
    }
  }
  const saveSoon = () => {
    if (!timer) timer = setTimeout(save, SAVE_MS);
  };
  form.addEventListener('input', saveSoon);
  form.addEventListener('change', saveSoon);
  // Programmatic changes (an example chosen, a file read) fire no input event: save on leaving.
  window.addEventListener('pagehide', save);

  return {
    save,
    forget() {
      try {
        localStorage.removeItem(key);
      } catch {
        // Nothing kept.
      }
    },
  };
}
