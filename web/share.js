// Sharing: the link (the URL holds the whole state, url_state.js) and the curl command that
// renders the same frame: the same request body, sent to this server's /v1/render, saved
// as PNG. A server with a token gets it from $LPV_SERVER_TOKEN, never spelled out.

import { token } from './api_client.js';

// POSIX shell single quotes: nothing inside is special but the quote itself.
function shellQuote(text) {
  return `'${text.replaceAll("'", `'\\''`)}'`;
}

function curlCommand(request, origin = location.origin) {
  const parts = ['curl', '-o', 'frame.png', '-H', shellQuote('Content-Type: application/json')];
  if (token()) parts.push('-H', '"Authorization: Bearer $LPV_SERVER_TOKEN"');
  parts.push('-d', shellQuote(JSON.stringify(request)), shellQuote(`${origin}/v1/render`));
  return parts.join(' ');
}

// The clipboard needs permission (and a secure context); the text is shown either way, so
// it can be selected by hand where copying is refused.
async function copy(text, status, what) {
  try {
    await navigator.clipboard.writeText(text);
    status.textContent = `${what} copied.`;
  } catch {
    status.textContent = `${what} shown: select it to copy (the browser refused the clipboard).`;
  }
}

export function attachShareButtons({ linkButton, curlButton, commandBox, status, state }) {
  linkButton.addEventListener('click', () => copy(location.href, status, 'Link'));
  curlButton.addEventListener('click', () => {
    const command = curlCommand(state.request);
    commandBox.textContent = command;
    commandBox.hidden = false;
    copy(command, status, 'curl command');
  });
  // A command on show follows the settings, so it never renders another frame than this one.
  state.addEventListener('change', () => {
    if (!commandBox.hidden) commandBox.textContent = curlCommand(state.request);
  });
}
