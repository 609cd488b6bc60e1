// A homework sheet as a student sees it: the title, the seed their numbers come from, one card per
// question on its panel, and "Hand in", which saves a small file and shows the same as a code.
// Lecture mode (the sheet's choice, or the switch) judges nothing on screen until the lecturer
// reveals a question: the "predict, then show" of a live class.
import { el } from '../../ui/el.js';
import { fileSlug } from '../../ui/format.js';
import { pageLocale } from '../../ui/safeLocale.js';
import { copyText, downloadText } from '../../host/exporters.js';
import { questionById } from '../questions.js';
import { questionParams, readAnswer } from '../gradeAnswer.js';
import { gradeHandIn } from '../gradeHandIn.js';
import { hashSeed, newSeed } from '../seededRandom.js';
import { readResume } from '../readResume.js';
import { scormInteraction } from '../scormInteraction.js';
import { handInToCode, makeHandIn } from '../sheetCodes.js';
import { openAnswerStore } from './answerStore.js';
import { buildQuestionCard } from './buildQuestionCard.js';
import { button, field, titledSection } from './formParts.js';

/** The seed in use and where it comes from (the sheet, the link, the LMS account, this browser). */
function chooseSeed(sheet, urlSeed, scorm, ownSeed) {
  if (sheet.seed) return { seed: sheet.seed, source: ' (the same for everyone on this sheet).' };
  if (urlSeed) return { seed: urlSeed, source: ', given in the link.' };
  // Hashed, so two long account ids that share a beginning still get different numbers.
  if (scorm?.learner.id) return { seed: `lms-${hashSeed(scorm.learner.id).toString(36)}`, source: ', from your course account: '
    + 'the same numbers wherever you open it.' };
  return { seed: ownSeed, source: ': the same seed gives the same numbers again, and your hand-in carries it.' };
}

/**
 * sheet: read by readSheet; code: its link code (the storage key); urlSeed: ?seed= or null;
 * scorm: the LMS connection (connectScorm.js) or null.
 */
export function showSheet(root, { sheet, code, urlSeed, scorm = null }) {
  document.title = `${sheet.title}: Fresnel Lab homework`;
  const store = openAnswerStore(code, sheet.items.length, newSeed);
  const { work } = store;
  const { seed, source } = chooseSeed(sheet, urlSeed, scorm, work.seed);
  store.forSeed(seed);
  const questions = sheet.items.map((item) => questionById(item.question));
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
  seedLine.append('Your numbers come from the seed ', el('code', 'hw-seed', seed), source);
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
  lectureLabel.append(lectureBox, ' Lecture mode: answers stay hidden until revealed');
  // In a course's LMS the score counts: the switch (and its reveal) is there only for a sheet set for class.
  lectureLabel.hidden = Boolean(scorm) && sheet.reveal !== 'lecturer';
  const revealAll = button('Reveal every answer', 'hw-reveal-all');
  head.append(el('h1', null, sheet.title), seedLine, field('Your name (goes into the hand-in)', name, 'hw-field hw-name'),
    lectureLabel, revealAll);
  if (scorm) head.append(el('p', 'hw-meta', 'This sheet is part of your course: handing in sends your score to its gradebook.'));
  else if (!store.kept()) head.append(el('p', 'notice notice-warning', 'This browser does not let the page keep your answers: '
    + 'hand in before you close it.'));
  if (resumeNotice) head.append(el('p', 'notice notice-warning hw-resume-notice', resumeNotice));
  root.append(head);

  const keep = () => {
    store.save();
    if (scorm && !scorm.save({ seed, answers: work.answers })) {
      status.textContent = 'The course could not keep these answers (too many, or it refused): hand in before you leave.';
    }
  };
  const lecture = () => lectureBox.checked;
  const frames = new Map(); // a panel frame's window → the frame, to fit each to the size it reports
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
      onFrame: (frame) => frames.set(frame.contentWindow, frame),
    });
    const reveal = button('Reveal the answer', 'hw-reveal');
    reveal.addEventListener('click', () => { card.reveal(); reveal.disabled = true; refreshAll(); });
    card.element.append(reveal);
    root.append(card.element);
    return { card, reveal };
  });
  window.addEventListener('message', (event) => {
    const frame = frames.get(event.source);
    if (!frame || event.data?.type !== 'fresnel-lab:size') return;
    const height = Number(event.data.height);
    if (Number.isFinite(height)) frame.style.height = `${Math.min(3000, Math.max(160, Math.ceil(height) + 2))}px`;
  });
  // The page's theme and projector mode reach the panels already open in their frames.
  window.addEventListener('fresnel-lab:theme', ({ detail }) => {
    for (const frame of frames.values()) {
      frame.contentWindow?.postMessage({ type: 'fresnel-lab:theme', theme: detail.scheme }, '*');
      frame.contentWindow?.postMessage({ type: 'fresnel-lab:projector', on: detail.projector }, '*');
    }
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

  const { section: handIn, heading: handInTitle } = titledSection('hw-hand-in', 'hand-in-title', 'Hand in');
  const send = button('Hand in: save the file and show the code', 'hw-send');
  const status = el('p', 'hw-hand-in-status');
  status.setAttribute('role', 'status');
  const codeField = el('textarea');
  codeField.readOnly = true;
  codeField.rows = 4;
  const codeLabel = field('Hand-in code (the same as the file; paste it where the lecturer asks)', codeField, 'hw-field hw-code');
  codeLabel.hidden = true;
  const copy = button('Copy the code', 'hw-copy');
  copy.hidden = true;
  // Asked on the page before handing in nothing or without a name (a hand-in cannot be taken back).
  const confirmBox = el('div', 'notice notice-warning hw-confirm');
  confirmBox.setAttribute('role', 'group');
  const confirmText = el('p', 'hw-confirm-text');
  confirmText.id = 'hw-confirm-text';
  confirmText.tabIndex = -1;
  confirmBox.setAttribute('aria-label', 'Before handing in');
  confirmBox.setAttribute('aria-describedby', confirmText.id);
  const anyway = button('Hand in anyway', 'hw-anyway');
  const goBack = button('Go back', 'hw-go-back');
  confirmBox.append(confirmText, anyway, goBack);
  confirmBox.hidden = true;
  handIn.append(handInTitle, el('p', null, 'The file and the code hold your answers, your seed, your name and the time; '
    + 'they are checked by recomputing every answer.'), send, confirmBox, status, codeLabel, copy);
  root.append(handIn);

  /** What is missing that a student would want to know before handing in: nothing answered, no name. */
  const missing = () => [
    !cards.every(({ card }) => card.answer() === null) ? ''
      : cards.length === 1 ? 'You have not answered the question.' : `You have answered none of the ${cards.length} questions.`,
    name.value.trim() ? '' : 'Your name is empty, so the lecturer cannot tell whose hand-in this is.',
  ].filter(Boolean);
  send.addEventListener('click', () => {
    const problems = missing();
    if (problems.length) {
      confirmText.textContent = `${problems.join(' ')} Hand in anyway?`;
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
    let sent = '';
    if (scorm) {
      const graded = gradeHandIn(record); // the same recomputation the lecturer's check does
      if (!graded.ok) sent = ` It could not be graded for the course: ${graded.problems.join(' ')}`;
      else if (scorm.report(graded.score, graded.total)) sent = ` Your score, ${graded.score} of ${graded.total}, `
        + `went to the course's gradebook.`;
      else sent = ' The course did not take the score: hand in the file or the code instead.';
    }
    status.textContent = `Handed in at ${new Date(record.time).toLocaleTimeString(pageLocale())}: `
      + `saved as ${filename}.${open ? ` ${open} of ${record.answers.length} questions have no answer.` : ''}${sent}`;
  }
  copy.addEventListener('click', async () => {
    codeField.select();
    status.textContent = (await copyText(codeField.value)) ? 'The code is copied.' : 'Copying was refused here: '
      + 'the code is selected, press Ctrl+C (⌘C).';
  });

  const back = el('p', 'hw-back');
  const link = el('a', null, 'Compose a sheet, or check a handed-in file');
  link.href = './homework.html';
  back.append(link);
  root.append(back);
  return { cards: cards.map(({ card }) => card) };
}
