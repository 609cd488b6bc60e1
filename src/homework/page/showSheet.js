// A homework sheet as a student sees it: the title, the seed their numbers come from, one card per
// question on its panel, and "Hand in", which saves a small file and shows the same as a code.
// Lecture mode (the sheet's choice, or the switch) judges nothing on screen until the lecturer
// reveals a question: the "predict, then show" of a live class.
import { el } from '../../ui/el.js';
import { copyText, downloadText } from '../../host/exporters.js';
import { questionById } from '../questions.js';
import { questionParams } from '../gradeAnswer.js';
import { newSeed } from '../seededRandom.js';
import { handInToCode, makeHandIn } from '../sheetCodes.js';
import { gradeHandIn } from '../readSheet.js';
import { openAnswerStore } from './answerStore.js';
import { buildQuestionCard } from './buildQuestionCard.js';
import { fileSlug } from './formatAnswer.js';


function button(text, className) {
  const b = el('button', className, text);
  b.type = 'button';
  return b;
}

/**
 * sheet: read by readSheet; code: its link code (the storage key); urlSeed: ?seed= or null;
 * scorm: the LMS connection (connectScorm.js) or null.
 */
export function showSheet(root, { sheet, code, urlSeed, scorm = null }) {
  document.title = `${sheet.title}: Fresnel Lab homework`;
  const store = openAnswerStore(code, sheet.items.length, newSeed);
  const { work } = store;
  const lmsSeed = scorm?.learner.id ? `lms-${scorm.learner.id}`.slice(0, 64) : null;
  const seed = sheet.seed ?? urlSeed ?? lmsSeed ?? work.seed;
  if (scorm) {
    // The LMS's copy of the answers wins: it follows the learner from one computer to another.
    const resumed = scorm.resume?.answers;
    if (Array.isArray(resumed) && resumed.length === work.answers.length) {
      resumed.forEach((a, i) => { work.answers[i] = typeof a === 'string' || typeof a === 'number' ? a : null; });
    }
    if (!work.name && scorm.learner.name) work.name = scorm.learner.name.slice(0, 100);
  }
  store.save();
  const keep = () => { store.save(); scorm?.save({ answers: work.answers }); };

  const head = el('header', 'hw-sheet-head');
  const title = el('h1', null, sheet.title);
  const seedLine = el('p', 'hw-meta');
  const seedSource = sheet.seed ? ' (the same for everyone on this sheet).' : urlSeed ? ' given in the link.'
    : lmsSeed ? ', from your course account: the same numbers wherever you open it.' : ': the same seed gives the same numbers again, and your hand-in carries it.';
  seedLine.append('Your numbers come from the seed ', el('code', 'hw-seed', seed), seedSource);
  const nameLabel = el('label', 'hw-field hw-name');
  const name = el('input');
  name.type = 'text';
  name.maxLength = 100;
  name.autocomplete = 'name';
  name.value = work.name;
  name.addEventListener('input', () => { work.name = name.value; store.save(); });
  nameLabel.append(el('span', null, 'Your name (goes into the hand-in)'), name);
  const lectureLabel = el('label', 'hw-switch');
  const lectureBox = el('input');
  lectureBox.type = 'checkbox';
  lectureBox.checked = sheet.reveal === 'lecturer';
  lectureLabel.append(lectureBox, ' Lecture mode: answers stay hidden until revealed');
  const revealAll = button('Reveal every answer', 'hw-reveal-all');
  head.append(title, seedLine, nameLabel, lectureLabel, revealAll);
  if (scorm) head.append(el('p', 'hw-meta', 'This sheet is part of your course: handing in sends your score to its gradebook.'));
  if (!store.kept() && !scorm) {
    head.append(el('p', 'notice notice-warning', 'This browser does not let the page keep your answers: hand in before you close it.'));
  }
  root.append(head);

  const lecture = () => lectureBox.checked;
  const cards = sheet.items.map((item, i) => {
    const question = questionById(item.question);
    const card = buildQuestionCard({
      number: i + 1,
      item,
      question,
      params: questionParams(question, seed),
      saved: work.answers[i],
      lecture,
      onAnswer: (answer) => { work.answers[i] = answer; keep(); },
    });
    const reveal = button('Reveal the answer', 'hw-reveal');
    reveal.addEventListener('click', () => { card.reveal(); reveal.disabled = true; });
    card.element.append(reveal);
    root.append(card.element);
    return { card, reveal };
  });
  const applyLecture = () => {
    root.classList.toggle('hw-lecture-mode', lecture());
    for (const { card } of cards) card.refresh();
  };
  lectureBox.addEventListener('change', applyLecture);
  revealAll.addEventListener('click', () => { for (const { card, reveal } of cards) { card.reveal(); reveal.disabled = true; } });
  applyLecture();

  const handIn = el('section', 'hw-hand-in');
  handIn.setAttribute('aria-labelledby', 'hand-in-title');
  const handInTitle = el('h2', null, 'Hand in');
  handInTitle.id = 'hand-in-title';
  const send = button('Hand in: save the file and show the code', 'hw-send');
  const status = el('p', 'hw-hand-in-status');
  status.setAttribute('role', 'status');
  const codeLabel = el('label', 'hw-field hw-code');
  const codeField = el('textarea');
  codeField.readOnly = true;
  codeField.rows = 4;
  codeLabel.append(el('span', null, 'Hand-in code (the same as the file; paste it where the lecturer asks)'), codeField);
  codeLabel.hidden = true;
  const copy = button('Copy the code', 'hw-copy');
  copy.hidden = true;
  handIn.append(handInTitle, el('p', null, 'The file and the code hold your answers, your seed, your name and the time; they are checked by recomputing every answer.'), send, status, codeLabel, copy);
  root.append(handIn);

  send.addEventListener('click', () => {
    const record = makeHandIn({ sheet, seed, name: work.name.trim(), answers: cards.map(({ card }) => card.answer()) });
    const filename = `fresnel-lab-${fileSlug(sheet.title)}-${fileSlug(seed)}.json`;
    downloadText(filename, `${JSON.stringify(record, null, 2)}\n`, 'application/json');
    codeField.value = handInToCode(record);
    codeLabel.hidden = false;
    copy.hidden = false;
    const open = record.answers.filter((a) => a === null).length;
    let sent = '';
    if (scorm) {
      const graded = gradeHandIn(record); // the same recomputation the lecturer's check does
      scorm.report(graded.score, graded.total);
      sent = ` Your score, ${graded.score} of ${graded.total}, went to the course's gradebook.`;
    }
    status.textContent = `Handed in at ${new Date(record.time).toLocaleTimeString()}: saved as ${filename}.${open ? ` ${open} of ${record.answers.length} questions have no answer.` : ''}${sent}`;
  });
  copy.addEventListener('click', async () => {
    codeField.select();
    status.textContent = (await copyText(codeField.value)) ? 'The code is copied.' : 'Copying was refused here: the code is selected, press Ctrl+C (⌘C).';
  });

  const back = el('p', 'hw-back');
  const link = el('a', null, 'Compose a sheet, or check a handed-in file');
  link.href = './homework.html';
  back.append(link);
  root.append(back);
  return { cards: cards.map(({ card }) => card) };
}
