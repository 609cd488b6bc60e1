// @ts-check
// The toolbar under a panel's controls: Copy link, Copy embed code, Export PNG, Export poster and
// Export CSV, and a status line that says what was done. What each button copies or saves comes
// from the host (the panel's link, embed code, picture, poster and table at the moment of the click).
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';
import { el } from '../ui/el.js';
import { copyText, downloadText, downloadUrl, offerForCopy, toCsv } from './exporters.js';

const t = messages('host', english);

/**
 * @param {string} id  the panel's id (file names)
 * @param {{ link: () => string, embed: () => string, png: () => string | null | undefined,
 *   poster: () => Promise<string | null>, csv: () => { columns: Record<string, unknown[]>, filename?: string } | null | undefined }} make
 */
export function createToolbar(id, make) {
  const element = el('div', 'toolbar');
  const status = el('span', 'toolbar-status');
  status.setAttribute('role', 'status');
  const buttons = {
    link: el('button', '', t('copyLink')),
    embed: el('button', '', t('copyEmbed')),
    png: /** @type {HTMLButtonElement} */ (el('button', '', t('exportPng'))),
    poster: el('button', '', t('exportPoster')),
    csv: /** @type {HTMLButtonElement} */ (el('button', '', t('exportCsv'))),
  };
  for (const b of Object.values(buttons)) /** @type {HTMLButtonElement} */ (b).type = 'button';
  element.append(...Object.values(buttons), status);

  const say = (text) => {
    status.textContent = text;
    setTimeout(() => { if (status.textContent === text) status.textContent = ''; }, 2500);
  };
  // Copied, or (the clipboard refused) offered selected for Ctrl+C.
  const copy = async (button, text, done, label) => {
    if (await copyText(text)) say(done);
    else {
      offerForCopy(button, text, label);
      say(t('pressCtrlC'));
    }
  };
  buttons.link.addEventListener('click', () => copy(buttons.link, make.link(), t('linkCopied'), t('linkField')));
  buttons.embed.addEventListener('click', () => copy(buttons.embed, make.embed(), t('embedCopied'), t('embedField')));
  buttons.png.addEventListener('click', () => {
    const url = make.png();
    if (url) downloadUrl(`fresnel-lab-${id}.png`, url);
  });
  buttons.poster.addEventListener('click', async () => {
    const url = await make.poster();
    if (url) downloadUrl(`fresnel-lab-${id}-poster.png`, url);
  });
  buttons.csv.addEventListener('click', () => {
    const table = make.csv();
    if (table) downloadText(table.filename ?? `fresnel-lab-${id}.csv`, toCsv(table.columns));
  });

  return {
    element,
    /** Which exports the mounted panel has (a panel without a picture has no PNG). */
    offer({ png, csv }) {
      buttons.png.disabled = !png;
      buttons.csv.disabled = !csv;
    },
  };
}
