// @ts-check
// A homework sheet as a student sees it: the title, the seed their numbers come from, one card per
// question on its panel, and "Hand in", which saves a small file and shows the same as a code.
// Lecture mode (the sheet's choice, or the switch) judges nothing on screen until the lecturer
// reveals a question: the "predict, then show" of a live class.
import { button, el } from '../../ui/el.js';
import { fileSlug } from '../../ui/format.js';
import { pageLocale } from '../../ui/safeLocale.js';
import { copyText, downloadText } from '../../host/exporters.js';
import { knownQuestion } from '../questions.js';
import { questionParams, readAnswer } from '../gradeAnswer.js';
import { gradeHandIn } from '../gradeHandIn.js';
import { hashSeed, newSeed } from '../seededRandom.js';
import { readResume } from '../readResume.js';
import { scormInteraction } from '../scormInteraction.js';
import { handInToCode, makeHandIn } from '../sheetCodes.js';
import { openAnswerStore } from './answerStore.js';
import { buildQuestionCard } from '../card/buildQuestionCard.js';
import { fitPanelFrames } from '../card/fitPanelFrames.js';
import { field, titledSection } from '../../ui/formParts.js';
import { withElement } from './withElement.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);

/** @typedef {ReturnType<typeof import('./connectScorm.js').connectScorm>} Scorm  the LMS connection, or null */

/**
 * The seed in use and where it comes from: 'sheet', 'link', 'course' (the LMS account) or 'browser'.
 * @param {import('../readSheet.js').Sheet} sheet
 * @param {string | null} urlSeed
 * @param {Scorm} scorm
 * @param {string} ownSeed
 */
function chooseSeed(sheet, urlSeed, scorm, ownSeed) {
  if (sheet.seed) return { seed: sheet.seed, source: 'sheet' };
  if (urlSeed) return { seed: urlSeed, source: 'link' };
  // Hashed, so two long account ids that share a beginning still get different numbers.
  if (scorm?.learner.id) return { seed: `lms-${hashSeed(scorm.learner.id).toString(36)}`, source: 'course' };
  return { seed: ownSeed, source: 'browser' };
}

/**
 * sheet: read by readSheet; code: its link code (the storage key); urlSeed: ?seed= or null;
 * scorm: the LMS connection (connectScorm.js) or null.
 * @param {HTMLElement} root
 * @param {{ sheet: import('../readSheet.js').Sheet, code: string, urlSeed: string | null, scorm?: Scorm }} shown
 */
export function showSheet(root, { sheet, code, urlSeed, scorm = null }) {
  document.title = t('student.documentTitle', { title: sheet.title });
  const store = openAnswerStore(code, sheet.items.length, newSeed);
  const { work } = store;
  const { seed, source } = chooseSeed(sheet, urlSeed, scorm, work.seed);
  store.forSeed(seed);
  const questions = sheet.items.map((item) => knownQuestion(item.question));
  const params = questions.map((q) => questionParams(q, seed));
  let resumeNotice = null;
  if (scorm) {
    // The LMS's copy of the answers wins: it follows the learner from one computer to another.
    const resumed = readResume(scorm.suspendData, { seed, classSeed: sheet.seed ?? null, questions, params });
    resumed.answers?.forEach((a, i) => { work.answers[i] = a; });
    resumeNotice = resumed.notice;
    if (!work.name && scorm.learner.name) work.name = scorm.learner.name.slice(0, 100);
  }
  const answers = work.answers.map((raw, i) => readAnswer(questions[i], params[i], raw));

  const head = el('header', 'hw-sheet-head');
  const seedLine = el('p', 'hw-meta');
  withElement(seedLine, (mark) => t('student.seedLine', { source, seed: mark }), el('code', 'hw-seed', seed));
  const name = el('input');
  name.type = 'text';
  name.maxLength = 100;
  name.autocomplete = 'name';
  name.value = work.name;
  name.addEventListener('input', () => { work.name = name.value; store.save(); });
  const lectureLabel = el('label', 'hw-switch');
  const lectureBox = el('input');
  lectureBox.type = 'checkbox';
  lectureBox.checked = sheet.reveal === 'lecturer';
  lectureLabel.append(lectureBox, ` ${t('student.lectureMode')}`);
  // In a course's LMS the score counts: the switch (and its reveal) is there only for a sheet set for class.
  lectureLabel.hidden = Boolean(scorm) && sheet.reveal !== 'lecturer';
  const revealAll = button(t('student.revealAll'), 'hw-reveal-all');
  head.append(el('h1', null, sheet.title), seedLine, field(t('student.name'), name, 'hw-name'), lectureLabel, revealAll);
  if (scorm) head.append(el('p', 'hw-meta', t('student.inCourse')));
  else if (!store.kept()) head.append(el('p', 'notice notice-warning', t('student.notKept')));
  if (resumeNotice) head.append(el('p', 'notice notice-warning hw-resume-notice', resumeNotice));
  root.append(head);

  const keep = () => {
    store.save();
    if (scorm && !scorm.save({ seed, answers: work.answers })) {
      status.textContent = t('student.courseNotKept');
    }
  };
  const lecture = () => lectureBox.checked;
  const frames = fitPanelFrames();
  /** @type {{ card: import('../card/buildQuestionCard.js').QuestionCard, reveal: HTMLButtonElement }[]} */
  let cards = [];
  const panelsAllowed = () => cards.every(({ card }, i) => questions[i].kind !== 'predict' || card.revealed()
    || (card.answer() !== null && !lecture()));
  const refreshAll = () => { for (const { card } of cards) card.refresh(); };
  cards = sheet.items.map((item, i) => {
    const card = buildQuestionCard({
      number: i + 1,
      item,
      question: questions[i],
      params: params[i],
      saved: answers[i],
      attempts: work.attempts[i],
      lecture,
      panelsAllowed: () => cards.length === sheet.items.length && panelsAllowed(),
      onAnswer: (answer) => {
        work.answers[i] = answer;
        work.attempts[i] = card.attempts();
        // Each check is one interaction in the LMS's reports; an empty box checked is no answer.
        if (scorm && answer !== null) {
          scorm.record(scormInteraction({ position: i + 1, question: questions[i], params: params[i], answer, at: new Date() }));
        }
        keep();
        if (questions[i].kind === 'predict') queueMicrotask(refreshAll); // a panel held back may now show
      },
      onFrame: frames.add,
    });
    const reveal = button(t('student.reveal'), 'hw-reveal');
    reveal.addEventListener('click', () => { card.reveal(); reveal.disabled = true; refreshAll(); });
    card.element.append(reveal);
    root.append(card.element);
    return { card, reveal };
  });
  const applyLecture = () => {
    root.classList.toggle('hw-lecture-mode', lecture());
    refreshAll();
  };
  lectureBox.addEventListener('change', applyLecture);
  revealAll.addEventListener('click', () => {
    for (const { card, reveal } of cards) { card.reveal(); reveal.disabled = true; }
    refreshAll();
  });
  applyLecture();

  const { section: handIn, heading: handInTitle } = titledSection('hw-hand-in', 'hand-in-title', t('student.handIn'));
  const send = button(t('student.send'), 'hw-send');
  const status = el('p', 'hw-hand-in-status');
  status.setAttribute('role', 'status');
  const codeField = el('textarea');
  codeField.readOnly = true;
  codeField.rows = 4;
  const codeLabel = field(t('student.code'), codeField, 'hw-code');
  codeLabel.hidden = true;
  const copy = button(t('student.copyCode'), 'hw-copy');
  copy.hidden = true;
  // Asked on the page before handing in nothing or without a name (a hand-in cannot be taken back).
  const confirmBox = el('div', 'notice notice-warning hw-confirm');
  confirmBox.setAttribute('role', 'group');
  const confirmText = el('p', 'hw-confirm-text');
  confirmText.id = 'hw-confirm-text';
  confirmText.tabIndex = -1;
  confirmBox.setAttribute('aria-label', t('student.beforeHandingIn'));
  confirmBox.setAttribute('aria-describedby', confirmText.id);
  const anyway = button(t('student.anyway'), 'hw-anyway');
  const goBack = button(t('student.goBack'), 'hw-go-back');
  confirmBox.append(confirmText, anyway, goBack);
  confirmBox.hidden = true;
  handIn.append(handInTitle, el('p', null, t('student.handInAbout')), send, confirmBox, status, codeLabel, copy);
  root.append(handIn);

  /** What is missing that a student would want to know before handing in: nothing answered, no name. */
  const missing = () => [
    cards.every(({ card }) => card.answer() === null) ? t('student.noneAnswered', { count: cards.length }) : '',
    name.value.trim() ? '' : t('student.noName'),
  ].filter(Boolean);
  send.addEventListener('click', () => {
    const problems = missing();
    if (problems.length) {
      confirmText.textContent = t('student.confirm', { problems: problems.join(' ') });
      confirmBox.hidden = false;
      confirmText.focus();
      return;
    }
    handInNow();
  });
  anyway.addEventListener('click', () => {
    confirmBox.hidden = true;
    handInNow();
  });
  goBack.addEventListener('click', () => {
    confirmBox.hidden = true;
    if (!name.value.trim()) name.focus();
    else send.focus();
  });

  function handInNow() {
    confirmBox.hidden = true;
    const record = makeHandIn({
      sheet, seed, name: work.name.trim(),
      answers: cards.map(({ card }) => card.answer()), attempts: cards.map(({ card }) => card.attempts()),
    });
    const filename = `fresnel-lab-${fileSlug(sheet.title)}-${fileSlug(seed)}.json`;
    downloadText(filename, `${JSON.stringify(record, null, 2)}\n`, 'application/json');
    codeField.value = handInToCode(record);
    codeLabel.hidden = false;
    copy.hidden = false;
    const open = record.answers.filter((a) => a === null).length;
    const said = [t('student.handedIn', { time: new Date(record.time).toLocaleTimeString(pageLocale()), file: filename })];
    if (open) said.push(t('student.unanswered', { open, count: record.answers.length }));
    if (scorm) {
      const graded = gradeHandIn(record); // the same recomputation the lecturer's check does
      if (!graded.ok) said.push(t('student.notGradedForCourse', { problems: graded.problems.join(' ') }));
      else if (scorm.report(graded.score, graded.total)) said.push(t('student.scoreSent', { score: graded.score, total: graded.total }));
      else said.push(t('student.scoreRefused'));
    }
    status.textContent = said.join(' ');
  }
  copy.addEventListener('click', async () => {
    codeField.select();
    status.textContent = (await copyText(codeField.value)) ? t('student.codeCopied') : t('student.copyRefused');
  });

  const back = el('p', 'hw-back');
  const link = el('a', null, t('student.back'));
  link.href = './homework.html';
  back.append(link);
  root.append(back);
  return { cards: cards.map(({ card }) => card) };
}
