// @ts-check
// The homework page without a sheet, the lecturer's: open a sheet file, compose a sheet, check
// handed-in files, grade a class. A module of its own, which homeworkPage.js fetches only where
// there is no sheet to show: a student's first picture does not wait for it.
import { showNotice } from '../../host/showNotice.js';
import { el } from '../../ui/el.js';
import { readTextFile } from '../../ui/formParts.js';
import { readSheet } from '../readSheet.js';
import { buildComposer, sheetUrl } from './buildComposer.js';
import { buildChecker } from './buildChecker.js';
import { buildClassSection } from './classView/buildClassSection.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);

/**
 * The lecturer's page in `root`: { composer, checker, classView }.
 * @param {HTMLElement} root
 */
export function showLecturerPage(root) {
  const intro = el('section', 'hw-intro');
  intro.append(el('h1', null, t('page.heading')), el('p', null, t('page.intro')));
  const openLabel = el('label', 'ui-field');
  const file = /** @type {HTMLInputElement} */ (el('input'));
  file.type = 'file';
  file.accept = '.json,application/json';
  openLabel.append(el('span', null, t('page.openSheet')), file);
  const openStatus = el('div');
  intro.append(openLabel, openStatus);
  file.addEventListener('change', async () => {
    const chosen = file.files?.[0];
    if (!chosen) return;
    const picked = await readTextFile(chosen);
    /** @type {import('../readSheet.js').ReadSheet} */
    let read;
    if (picked.text === undefined) {
      read = { ok: false, problems: picked.problems ?? [] };
    } else {
      try {
        read = readSheet(JSON.parse(picked.text));
      } catch {
        read = { ok: false, problems: [t('page.notSheetJson')] };
      }
    }
    openStatus.replaceChildren();
    if (read.ok) window.location.assign(sheetUrl(read.sheet));
    else showNotice(openStatus, t('page.unusableFile', { file: chosen.name }), read.problems, { kind: 'error' });
  });
  root.append(intro);
  const composer = buildComposer(root);
  const checker = buildChecker(root);
  const classView = buildClassSection(root);
  return { composer, checker, classView };
}
