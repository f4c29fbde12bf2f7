// Asks for the server's access token in a small modal form (<dialog id="token-dialog">).
// askToken(refused) resolves to the token typed in, or null if the user gives up.

export function createTokenForm(dialog) {
  const form = dialog.querySelector('form');
  const input = dialog.querySelector('#token-input');
  const message = dialog.querySelector('#token-message');
  const cancel = dialog.querySelector('#token-cancel');

  return function askToken(refused) {
    return new Promise((resolve) => {
      message.textContent = refused
        ? 'The server refused the token in use. Enter the right one.'
        : 'This server needs an access token (the --token it was started with).';
      input.value = '';
      const finish = (value) => {
        form.removeEventListener('submit', onSubmit);
        cancel.removeEventListener('click', onCancel);
        dialog.removeEventListener('cancel', onCancel);
        if (dialog.open) dialog.close();
        resolve(value);
      };
      const onSubmit = (event) => {
        event.preventDefault();
        const token = input.value.trim();
        if (token) finish(token);
        else input.focus();
      };
      const onCancel = (event) => {
        event.preventDefault();
        finish(null);
      };
      form.addEventListener('submit', onSubmit);
      cancel.addEventListener('click', onCancel);
      dialog.addEventListener('cancel', onCancel);
      dialog.showModal();
      input.focus();
    });
  };
}
