// @ts-check
// homework.html: with ?sheet=CODE (or a sheet written into the page, in a SCORM package), the sheet
// a student works on (showSheet); without one, the lecturer's page: open a sheet file, compose a
// sheet, check handed-in files, grade a class (lecturerPage.js). A sheet that cannot be read is
// refused with its reasons, and the lecturer's page is shown under them. The page speaks the
// language the sheet was made in (its `lang`), unless the link asks for another (?lang=). Each of
// the two is a module of its own, fetched while the language loads: a page takes only the one it shows.
import './styles.css';
import './homework/page/homework.css';
import { setupPageControls } from './host/setupPageControls.js';
import { showNotice } from './host/showNotice.js';
import { installPageFaults } from './host/panelFaults.js';
import { own } from './host/own.js';
import { readSheet, sheetLanguage } from './homework/readSheet.js';
import { sheetFromCode } from './homework/sheetCodes.js';
import './homework/page/classView/classView.css';
import { startPageLanguage } from './i18n/pageLanguage.js';
import english from 'virtual:messages/en/homework';
import { messages } from './i18n/messages.js';
import { pageElement } from './ui/pageElement.js';

const t = messages('homework', english);

const search = new URLSearchParams(window.location.search);
// A SCORM package carries its sheet in the page (buildScormPackage.js), and then that sheet and
// the learner's seed are the only ones: a ?sheet= or ?seed= added to its address is not read (the
// LMS would be sent the score of another sheet). Elsewhere a link carries the sheet in ?sheet=.
const carried = document.getElementById('fresnel-lab-sheet');
const inPackage = carried?.dataset.scorm === '1';
const code = inPackage ? carried.textContent.trim() : search.get('sheet');

/**
 * The language a sheet's code carries, where it is one of the lab's (the rest of the sheet is read later).
 * @param {string | null} sheetCode
 */
function carriedLanguage(sheetCode) {
  if (sheetCode === null) return null;
  const decoded = sheetFromCode(sheetCode);
  const lang = decoded.ok ? own(decoded.data, 'lang') ?? null : null;
  return sheetLanguage(lang) ? lang : null;
}

const lecturerModule = () => import('./homework/page/lecturerPage.js');
// Fetched now, while the language loads: the sheet's parts where a link gives one (it is read, and
// may be refused, once the language is here), else the lecturer's page.
const sheetModule = code === null ? null : import('./homework/page/showSheet.js');
const lecturer = code === null ? lecturerModule() : null;
const scormModule = inPackage ? import('./homework/page/connectScorm.js') : null;

// The language first, so every word below is in it.
const language = await startPageLanguage({ carried: carriedLanguage(code) });
setupPageControls(pageElement('.page-controls'), {});
const root = pageElement('#homework');
if (language.problem) showNotice(root, t('page.languageProblem'), [language.problem]);
installPageFaults((title, lines) => showNotice(root, title, lines, { kind: 'error' }));
/** @type {{ homework: object | null }} the page's hook for the browser tests: the sheet's view, or the lecturer's parts */
const lab = { homework: null };
window.fresnelLab = lab;

if (code === null) {
  lab.homework = (await (lecturer ?? lecturerModule())).showLecturerPage(root); // fetched above: code is null
} else {
  const decoded = sheetFromCode(code);
  /** @type {import('./homework/readSheet.js').ReadSheet} */
  const read = decoded.ok ? readSheet(decoded.data) : { ok: false, problems: decoded.problems ?? [] };
  if (read.ok) {
    const seed = inPackage ? null : search.get('seed')?.trim().slice(0, 64) || null;
    const scorm = scormModule ? (await scormModule).connectScorm() : null;
    const { showSheet } = await (sheetModule ?? import('./homework/page/showSheet.js')); // fetched above: code is not null
    lab.homework = showSheet(root, { sheet: read.sheet, code, urlSeed: seed, scorm });
  } else {
    lab.homework = (await lecturerModule()).showLecturerPage(root);
    showNotice(root, t('page.unusableLink'), [...read.problems, t('page.askAgain')], { kind: 'error' });
  }
}
