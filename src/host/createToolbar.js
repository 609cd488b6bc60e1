// @ts-check
// The toolbar under a panel's controls: Copy link, Copy embed code, Export PNG, Export poster and
// Export CSV, and a status line that says what was done. What each button copies or saves comes
// from the host (the panel's link, embed code, picture, poster and table at the moment of the click).
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';
import { button, el } from '../ui/el.js';
import { copyText, downloadText, downloadUrl, offerForCopy, toCsv } from './exporters.js';

const t = messages('host', english);

/**
 * @param {string} id  the panel's id (file names)
 * @param {{ link: () => string, embed: () => string, png: () => string | null | undefined,
 *   poster: () => Promise<string | null>, csv: () => import('./panelContract.js').CsvTable | null | undefined }} make
 */
export function createToolbar(id, make) {
  const element = el('div', 'toolbar');
  const status = el('span', 'toolbar-status');
  status.setAttribute('role', 'status');
  const buttons = {
    link: button(t('copyLink')),
    embed: button(t('copyEmbed')),
    png: button(t('exportPng')),
    poster: button(t('exportPoster')),
    csv: button(t('exportCsv')),
  };
  element.append(...Object.values(buttons), status);

  const say = (/** @type {string} */ text) => {
    status.textContent = text;
    setTimeout(() => { if (status.textContent === text) status.textContent = ''; }, 2500);
  };
  /**
   * Copied, or (the clipboard refused) offered selected for Ctrl+C.
   * @param {HTMLButtonElement} from @param {string} text @param {string} done @param {string} label
   */
  const copy = async (from, text, done, label) => {
    if (await copyText(text)) say(done);
    else {
      offerForCopy(from, text, label);
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
    else say(t('posterNoCanvas'));
  });
  buttons.csv.addEventListener('click', () => {
    const table = make.csv();
    if (table) downloadText(table.filename ?? `fresnel-lab-${id}.csv`, toCsv(table.columns));
  });

  return {
    element,
    /**
     * Which exports the mounted panel has (a panel without a picture has no PNG).
     * @param {Pick<import('./panelContract.js').PanelInstance, 'png' | 'csv'>} instance
     */
    offer({ png, csv }) {
      buttons.png.disabled = !png;
      buttons.csv.disabled = !csv;
    },
  };
}
