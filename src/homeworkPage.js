// homework.html: with ?sheet=CODE (or a sheet written into the page, in a SCORM package), the sheet
// a student works on (showSheet); without one, the lecturer's page: open a sheet file, compose a
// sheet, check handed-in files, grade a class. A sheet that cannot be read is refused with its
// reasons, and the lecturer's page is shown under them. The page speaks the language the sheet was
// made in (its `lang`), unless the link asks for another (?lang=).
import './styles.css';
import './homework/page/homework.css';
import { setupPageControls } from './host/setupPageControls.js';
import { showNotice } from './host/showNotice.js';
import { installPageFaults } from './host/panelFaults.js';
import { own } from './host/own.js';
import { el } from './ui/el.js';
import { readSheet, sheetLanguage } from './homework/readSheet.js';
import { sheetFromCode } from './homework/sheetCodes.js';
import { showSheet } from './homework/page/showSheet.js';
import { buildComposer, sheetUrl } from './homework/page/buildComposer.js';
import { buildChecker } from './homework/page/buildChecker.js';
import { buildClassSection } from './homework/page/classView/buildClassSection.js';
import './homework/page/classView/classView.css';
import { connectScorm } from './homework/page/connectScorm.js';
import { readTextFile } from './ui/formParts.js';
import { startPageLanguage } from './i18n/pageLanguage.js';
import english from 'virtual:messages/en/homework';
import { messages } from './i18n/messages.js';

const t = messages('homework', english);

const search = new URLSearchParams(window.location.search);
// A SCORM package carries its sheet in the page (buildScormPackage.js), and then that sheet and
// the learner's seed are the only ones: a ?sheet= or ?seed= added to its address is not read (the
// LMS would be sent the score of another sheet). Elsewhere a link carries the sheet in ?sheet=.
const carried = document.getElementById('fresnel-lab-sheet');
const inPackage = carried?.dataset.scorm === '1';
const code = inPackage ? carried.textContent.trim() : search.get('sheet');

/** The language a sheet's code carries, where it is one of the lab's (the rest of the sheet is read later). */
function carriedLanguage(sheetCode) {
  if (sheetCode === null) return null;
  const decoded = sheetFromCode(sheetCode);
  const lang = decoded.ok ? own(decoded.data, 'lang') ?? null : null;
  return sheetLanguage(lang) ? lang : null;
}

// The language first, so every word below is in it.
const language = await startPageLanguage({ carried: carriedLanguage(code) });
setupPageControls(document.querySelector('.page-controls'), {});
const root = document.getElementById('homework');
if (language.problem) showNotice(root, t('page.languageProblem'), [language.problem]);
installPageFaults((title, lines) => showNotice(root, title, lines, { kind: 'error' }));
window.fresnelLab = { homework: null };

function lecturerPage() {
  const intro = el('section', 'hw-intro');
  intro.append(el('h1', null, t('page.heading')), el('p', null, t('page.intro')));
  const openLabel = el('label', 'ui-field');
  const file = el('input');
  file.type = 'file';
  file.accept = '.json,application/json';
  openLabel.append(el('span', null, t('page.openSheet')), file);
  const openStatus = el('div');
  intro.append(openLabel, openStatus);
  file.addEventListener('change', async () => {
    const chosen = file.files[0];
    if (!chosen) return;
    const picked = await readTextFile(chosen);
    let read = picked;
    if (picked.ok) {
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
  window.fresnelLab.homework = { composer, checker, classView };
}

if (code === null) {
  lecturerPage();
} else {
  const decoded = sheetFromCode(code);
  const read = decoded.ok ? readSheet(decoded.data) : decoded;
  if (read.ok) {
    const seed = inPackage ? null : search.get('seed')?.trim().slice(0, 64) || null;
    const scorm = inPackage ? connectScorm() : null;
    window.fresnelLab.homework = showSheet(root, { sheet: read.sheet, code, urlSeed: seed, scorm });
  } else {
    lecturerPage();
    showNotice(root, t('page.unusableLink'), [...read.problems, t('page.askAgain')], { kind: 'error' });
  }
}
