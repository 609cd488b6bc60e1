// compose.html: the lecture composer. A catalogue to add from, the lecture as an ordered list of
// items to edit, and the lecture's link, file and exports. It opens with the lecture of
// ?lecture=CODE (to edit a shared lecture), else the work kept in this browser, else an empty
// lecture; whatever cannot be read is named above it, never a blank page.
import '../styles.css';
import '../homework/page/homework.css';
import './compose.css';
import { setupPageControls } from '../host/setupPageControls.js';
import { startPageLanguage } from '../i18n/pageLanguage.js';
import { showNotice } from '../host/showNotice.js';
import { installPageFaults } from '../host/panelFaults.js';
import { button, el } from '../ui/el.js';
import { field } from '../homework/page/formParts.js';
import { lectureFromCode } from '../lecture/lectureLink.js';
import { defaultLecture } from '../lecture/defaultLecture.js';
import { LECTURE_CAPS } from '../lecture/readLecture.js';
import {
  addItem, draftData, draftFromLecture, draftToLecture, duplicateItem, emptyDraft, itemIndex, itemName, moveItem, moveItemTo,
  panelItem, questionItem, removeItem, setTitle, textItem, updateItem,
} from './composerModel.js';
import { clearDraft, loadDraft, saveDraft } from './draftStore.js';
import { buildCatalogue } from './buildCatalogue.js';
import { buildLectureList } from './buildLectureList.js';
import { buildItemEditor } from './buildItemEditor.js';
import { buildShare } from './buildShare.js';

// The language first, so every word below is in it.
const language = await startPageLanguage();
setupPageControls(document.querySelector('.page-controls'), {});
const root = document.getElementById('composer');
const notices = el('div', 'cp-notices');
installPageFaults((title, lines) => showNotice(notices, title, lines, { kind: 'error' }));
if (language.problem) showNotice(notices, 'The page could not load its language, so it is in English:', [language.problem]);

const intro = el('section', 'hw-intro cp-intro');
intro.append(el('h1', null, 'Compose a lecture'),
  el('p', null, 'Pick panels, texts and questions to the room, put them in your order, '
    + 'give each your own words and the view it starts from. '
    + 'The lecture is a link: present it, share it, or carry it as one offline file or a reveal.js deck. Nothing leaves this browser.'));
const startEmpty = button('Start an empty lecture');
const startDefault = button('Start from the lab’s own lecture');
const starts = el('div', 'cp-row');
starts.append(startEmpty, startDefault);
intro.append(starts, notices);
root.append(intro); // first, so that a fault while the rest is built is said on the page

// The draft, where it comes from: the link, else what this browser kept.
const search = new URLSearchParams(window.location.search);
let draft = emptyDraft();
let kept = true;
let before = null; // what this browser kept, when a link's lecture is shown instead
if (search.has('lecture')) {
  const read = lectureFromCode(search.get('lecture') ?? '');
  if (read.ok) {
    draft = draftFromLecture(read.lecture);
    showNotice(notices, 'Parts of this lecture’s link could not be used:', read.problems);
    before = loadDraft().lecture;
  } else {
    kept = false; // the work kept in this browser is not overwritten by a link that could not be read
    showNotice(notices, 'This lecture link cannot be opened:',
      [...read.problems, 'The lecture kept in this browser, if any, is shown instead.'], { kind: 'error' });
  }
}
if (!search.has('lecture') || !kept) {
  const stored = loadDraft();
  if (stored.lecture) draft = draftFromLecture(stored.lecture);
  showNotice(notices, 'The lecture kept in this browser:', stored.problems);
  kept = true;
}

const title = /** @type {HTMLInputElement} */ (el('input', 'cp-title'));
title.type = 'text';
title.maxLength = LECTURE_CAPS.title;
const lectureSection = el('section', 'cp-lecture');
lectureSection.setAttribute('aria-labelledby', 'cp-lecture-title');
const lectureHeading = el('h2', null, 'Your lecture');
lectureHeading.id = 'cp-lecture-title';

const list = buildLectureList({
  actions: {
    move: (key, delta) => moved(key, moveItem(draft, key, delta)),
    moveTo: (key, index) => moved(key, moveItemTo(draft, key, index)),
    duplicate(key) {
      const copy = duplicateItem(draft, key);
      if (!copy.key) return list.announce(`A lecture holds at most ${LECTURE_CAPS.items} items.`);
      commit(copy.draft);
      list.focusItem(copy.key);
      list.announce(`Duplicated: “${itemName(draft.items[itemIndex(draft, copy.key)])}” is item ${itemIndex(draft, copy.key) + 1}.`);
    },
    remove(key) {
      const at = itemIndex(draft, key);
      const name = itemName(draft.items[at]);
      commit(removeItem(draft, key));
      const next = draft.items[Math.min(at, draft.items.length - 1)];
      if (next) list.focusItem(next.key);
      else title.focus();
      list.announce(`Removed “${name}”. ${draft.items.length} item${draft.items.length === 1 ? '' : 's'} left.`);
    },
  },
  editor: (item) => buildItemEditor(item, { patch: (fields) => commit(updateItem(draft, item.key, fields)) }),
});

function moved(key, next) {
  const from = itemIndex(draft, key);
  commit(next);
  const to = itemIndex(draft, key);
  const name = itemName(draft.items[to]);
  list.announce(to === from
    ? `“${name}” is already ${to === 0 ? 'first' : 'last'}.`
    : `Moved “${name}” to position ${to + 1} of ${draft.items.length}.`);
}

const share = buildShare({
  onOpen(lecture, problems, fileName) {
    replace(draftFromLecture(lecture));
    notices.replaceChildren();
    showNotice(notices, `Parts of ${fileName} could not be used:`, problems);
    share.say(`Opened ${fileName}: ${lecture.items.length} items.`);
  },
});

function commit(next) {
  draft = next;
  list.sync(draft);
  share.update(draftToLecture(draft));
  if (kept && !saveDraft(draftData(draft))) {
    kept = false;
    showNotice(notices, 'Not kept:',
      ['This browser refuses the page its storage, so the lecture is lost when the page closes: download it as a file.']);
  }
}

function replace(next) {
  draft = next;
  title.value = draft.title;
  list.reset(draft);
  commit(draft);
}

function add(item) {
  const added = addItem(draft, item);
  if (!added.key) return list.announce(`A lecture holds at most ${LECTURE_CAPS.items} items.`);
  commit(added.draft);
  list.announce(`Added “${itemName(draft.items[itemIndex(draft, added.key)])}” `
    + `as item ${itemIndex(draft, added.key) + 1} of ${draft.items.length}.`);
}

const catalogue = buildCatalogue({
  panel: (id) => add(panelItem(id)),
  question: (id) => add(questionItem(id)),
  text: () => add(textItem()),
});

title.addEventListener('input', () => commit(setTitle(draft, title.value)));
lectureSection.append(lectureHeading, field('Title of the lecture', title), list.element);
const columns = el('div', 'cp-columns');
columns.append(catalogue, lectureSection);
root.append(columns, share.element);

const confirmReplace = () => !draft.items.length || window.confirm(`Replace the ${draft.items.length} items of this lecture?`);
startEmpty.addEventListener('click', () => {
  if (confirmReplace()) { clearDraft(); replace(emptyDraft()); list.announce('An empty lecture.'); }
});
startDefault.addEventListener('click', () => {
  if (!confirmReplace()) return;
  replace(draftFromLecture(defaultLecture()));
  list.announce(`The lab’s own lecture: ${draft.items.length} panels.`);
});

// Shown, not yet kept: the work kept before stays until this lecture is changed, and can be taken back.
kept = false;
replace(draft);
kept = true;
if (before?.items.length) {
  const note = showNotice(notices, 'This link’s lecture is shown for editing.', [
    `The lecture kept in this browser (“${before.title}”, ${before.items.length} items) is replaced by it as soon as you change it.`]);
  const back = button('Edit the kept lecture instead');
  back.addEventListener('click', () => { replace(draftFromLecture(before)); note?.remove(); list.announce(`“${before.title}” is back.`); });
  note?.append(back);
}
window.fresnelLab = { composer: { draft: () => draft, lecture: () => draftToLecture(draft).lecture } };
