// @ts-check
// compose.html: the lecture composer. A catalogue to add from, the lecture as an ordered list of
// items to edit, and the lecture's link, file and exports. It opens with the lecture of
// ?lecture=CODE (to edit a shared lecture), else the work kept in this browser, else an empty
// lecture; whatever cannot be read is named above it, never a blank page. A lecture keeps its own
// language, shown and changed beside its title; a link's lecture opens the page in it (unless the
// link asks for another with ?lang=), as the lecture page does.
import '../styles.css';
import './compose.css';
import { setupPageControls } from '../host/setupPageControls.js';
import { startPageLanguage } from '../i18n/pageLanguage.js';
import { showNotice } from '../host/showNotice.js';
import { installPageFaults } from '../host/panelFaults.js';
import { button, el } from '../ui/el.js';
import { fixed } from '../ui/format.js';
import { field } from '../ui/formParts.js';
import { lectureFromCode } from '../lecture/lectureLink.js';
import { lectureCodeLanguage } from '../lecture/lectureCode.js';
import { LANGUAGES, languageById } from '../i18n/languages.js';
import { defaultLecture } from '../lecture/defaultLecture.js';
import { LECTURE_CAPS } from '../lecture/readLecture.js';
import {
  addItem, draftData, draftFromLecture, draftToLecture, duplicateItem, emptyDraft, itemIndex, itemName, moveItem, moveItemTo,
  panelItem, questionItem, removeItem, setLanguage, setTitle, textItem, updateItem,
} from './composerModel.js';
import { clearDraft, loadDraft, saveDraft } from './draftStore.js';
import { buildCatalogue } from './buildCatalogue.js';
import { buildLectureList } from './buildLectureList.js';
import { buildShare } from './buildShare.js';
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { pageElement } from '../ui/pageElement.js';

const t = messages('compose', english);

const search = new URLSearchParams(window.location.search);
// The language first, so every word below is in it: a link's lecture carries its own.
const language = await startPageLanguage({ carried: search.has('lecture') ? lectureCodeLanguage(search.get('lecture')) : null });
setupPageControls(pageElement('.page-controls'), {});
const root = pageElement('#composer');
const notices = el('div', 'cp-notices');
installPageFaults((title, lines) => showNotice(notices, title, lines, { kind: 'error' }));
if (language.problem) showNotice(notices, t('languageProblem'), [language.problem]);

const intro = el('section', 'cp-intro');
intro.append(el('h1', null, t('heading')), el('p', null, t('intro')));
const startEmpty = button(t('startEmpty'));
const startDefault = button(t('startDefault'));
const starts = el('div', 'cp-row');
starts.append(startEmpty, startDefault);
intro.append(starts, notices);
root.append(intro); // first, so that a fault while the rest is built is said on the page

// The draft, where it comes from: the link, else what this browser kept.
let draft = emptyDraft();
let kept = true;
/** @type {import('../lecture/readLecture.js').Lecture | null} what this browser kept, when a link's lecture is shown instead */
let before = null;
if (search.has('lecture')) {
  const read = lectureFromCode(search.get('lecture') ?? '');
  if (read.ok) {
    draft = draftFromLecture(read.lecture);
    showNotice(notices, t('linkPartsRefused'), read.problems);
    before = loadDraft().lecture;
  } else {
    kept = false; // the work kept in this browser is not overwritten by a link that could not be read
    showNotice(notices, t('linkRefused'), [...read.problems, t('linkRefusedKept')], { kind: 'error' });
  }
}
if (!search.has('lecture') || !kept) {
  const stored = loadDraft();
  if (stored.lecture) draft = draftFromLecture(stored.lecture);
  showNotice(notices, t('keptProblems'), stored.problems);
  kept = true;
}

const title = /** @type {HTMLInputElement} */ (el('input', 'cp-title'));
title.type = 'text';
title.maxLength = LECTURE_CAPS.title;
// The lecture's language: its own, whatever this page's (a pseudo-locale is listed while a lecture has it).
const languageSelect = /** @type {HTMLSelectElement} */ (el('select', 'cp-language'));
const languageHint = el('p', 'cp-hint', t('languageHint'));
languageHint.id = 'cp-language-hint';
languageSelect.setAttribute('aria-describedby', languageHint.id);
/** @param {string} lang */
function showLanguage(lang) {
  const own = languageById(lang);
  const choices = own && !LANGUAGES.includes(own) ? [...LANGUAGES, own] : LANGUAGES;
  languageSelect.replaceChildren(...choices.map((l) => Object.assign(new Option(l.name, l.id), { lang: l.id }))); // each named in itself
  languageSelect.value = lang;
}
const lectureSection = el('section', 'cp-lecture');
lectureSection.setAttribute('aria-labelledby', 'cp-lecture-title');
const lectureHeading = el('h2', null, t('yourLecture'));
lectureHeading.id = 'cp-lecture-title';

const list = buildLectureList({
  actions: {
    move: (key, delta) => moved(key, moveItem(draft, key, delta)),
    moveTo: (key, index) => moved(key, moveItemTo(draft, key, index)),
    duplicate(key) {
      const copy = duplicateItem(draft, key);
      if (!copy.key) {
        list.announce(t('full', { max: fixed(LECTURE_CAPS.items, 0) }));
        return;
      }
      commit(copy.draft);
      list.focusItem(copy.key);
      const at = itemIndex(draft, copy.key);
      list.announce(t('duplicated', { name: itemName(draft.items[at]), n: fixed(at + 1, 0) }));
    },
    remove(key) {
      const at = itemIndex(draft, key);
      const name = itemName(draft.items[at]);
      commit(removeItem(draft, key));
      const next = draft.items[Math.min(at, draft.items.length - 1)];
      if (next) list.focusItem(next.key);
      else title.focus();
      list.announce(t('removed', { name, count: draft.items.length, n: fixed(draft.items.length, 0) }));
    },
  },
  editor: itemEditor,
});

/** @type {Promise<typeof import('./buildItemEditor.js')> | null} */
let editors = null;
/**
 * An item's editor, in a place of its own until its module is here: the editors (a panel's start
 * state, the controls' words, the Markdown preview) are fetched with the first item, so an empty
 * composer draws without them.
 * @param {import('./composerModel.js').ItemDraft} item
 */
function itemEditor(item) {
  const place = el('div', 'cp-item-body');
  (editors ??= import('./buildItemEditor.js')).then(({ buildItemEditor }) => {
    place.replaceWith(buildItemEditor(item, { patch: (fields) => commit(updateItem(draft, item.key, fields)) }));
  });
  return place;
}

/**
 * @param {string} key
 * @param {import('./composerModel.js').Draft} next
 */
function moved(key, next) {
  const from = itemIndex(draft, key);
  commit(next);
  const to = itemIndex(draft, key);
  const name = itemName(draft.items[to]);
  list.announce(to === from
    ? t('alreadyThere', { name, end: to === 0 ? 'first' : 'last' })
    : t('moved', { name, n: fixed(to + 1, 0), of: fixed(draft.items.length, 0) }));
}

const share = buildShare({
  onOpen(lecture, problems, fileName) {
    replace(draftFromLecture(lecture));
    notices.replaceChildren();
    showNotice(notices, t('filePartsRefused', { file: fileName }), problems);
    share.say(t('fileOpened', { file: fileName, count: lecture.items.length, n: fixed(lecture.items.length, 0) }));
  },
});

/** @param {import('./composerModel.js').Draft} next */
function commit(next) {
  draft = next;
  list.sync(draft);
  share.update(draftToLecture(draft));
  if (kept && !saveDraft(draftData(draft))) {
    kept = false;
    showNotice(notices, t('notKept'), [t('notKeptWhy')]);
  }
}

/** @param {import('./composerModel.js').Draft} next */
function replace(next) {
  draft = next;
  title.value = draft.title;
  showLanguage(draft.lang);
  list.reset(draft);
  commit(draft);
}

/** @param {import('./composerModel.js').NewItem} item */
function add(item) {
  const added = addItem(draft, item);
  if (!added.key) {
    list.announce(t('full', { max: fixed(LECTURE_CAPS.items, 0) }));
    return;
  }
  commit(added.draft);
  const at = itemIndex(draft, added.key);
  list.announce(t('added', { name: itemName(draft.items[at]), n: fixed(at + 1, 0), of: fixed(draft.items.length, 0) }));
}

const catalogue = buildCatalogue({
  panel: (id) => add(panelItem(id)),
  question: (id) => add(questionItem(id)),
  text: () => add(textItem()),
});

title.addEventListener('input', () => commit(setTitle(draft, title.value)));
languageSelect.addEventListener('change', () => commit(setLanguage(draft, languageSelect.value)));
lectureSection.append(lectureHeading, field(t('titleField'), title), field(t('languageField'), languageSelect), languageHint, list.element);
const columns = el('div', 'cp-columns');
columns.append(catalogue, lectureSection);
root.append(columns, share.element);

const confirmReplace = () => !draft.items.length
  || window.confirm(t('confirmReplace', { count: draft.items.length, n: fixed(draft.items.length, 0) }));
startEmpty.addEventListener('click', () => {
  if (confirmReplace()) { clearDraft(); replace(emptyDraft()); list.announce(t('emptyStarted')); }
});
startDefault.addEventListener('click', () => {
  if (!confirmReplace()) return;
  replace(draftFromLecture(defaultLecture()));
  list.announce(t('defaultStarted', { count: draft.items.length, n: fixed(draft.items.length, 0) }));
});

// Shown, not yet kept: the work kept before stays until this lecture is changed, and can be taken back.
kept = false;
replace(draft);
kept = true;
if (before?.items.length) {
  const note = showNotice(notices, t('linkShown'), [
    t('linkShownKept', { title: before.title, count: before.items.length, n: fixed(before.items.length, 0) })]);
  const back = button(t('editKept'));
  const keptLecture = before;
  back.addEventListener('click', () => {
    replace(draftFromLecture(keptLecture));
    note?.remove();
    list.announce(t('keptBack', { title: keptLecture.title }));
  });
  note?.append(back);
}
window.fresnelLab = { composer: { draft: () => draft, lecture: () => draftToLecture(draft).lecture } };
