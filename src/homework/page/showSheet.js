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
import { openAnswerStore } from './answerStore.js';
import { buildQuestionCard } from './buildQuestionCard.js';

const slug = (text) => text.toLowerCase().normalize('NFKD').replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '').slice(0, 40) || 'sheet';

function button(text, className) {
  const b = el('button', className, text);
  b.type = 'button';
  return b;
}

/** sheet: read by readSheet; code: its link code (the storage key); urlSeed: ?seed= or null. */
export function showSheet(root, { sheet, code, urlSeed }) {
  document.title = `${sheet.title}: Fresnel Lab homework`;
  const store = openAnswerStore(code, sheet.items.length, newSeed);
  const { work } = store;
  const seed = sheet.seed ?? urlSeed ?? work.seed;
  if (!sheet.seed && !urlSeed) store.save();

  const head = el('header', 'hw-sheet-head');
  const title = el('h1', null, sheet.title);
  const seedLine = el('p', 'hw-meta');
  seedLine.append('Your numbers come from the seed ', el('code', 'hw-seed', seed),
    sheet.seed ? ' (the same for everyone on this sheet).' : urlSeed ? ' given in the link.' : ': the same seed gives the same numbers again, and your hand-in carries it.');
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
  if (!store.kept()) {
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
      onAnswer: (answer) => { work.answers[i] = answer; store.save(); },
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
    const filename = `fresnel-lab-${slug(sheet.title)}-${slug(seed)}.json`;
    downloadText(filename, `${JSON.stringify(record, null, 2)}\n`, 'application/json');
    codeField.value = handInToCode(record);
    codeLabel.hidden = false;
    copy.hidden = false;
    const open = record.answers.filter((a) => a === null).length;
    status.textContent = `Handed in at ${new Date(record.time).toLocaleTimeString()}: saved as ${filename}.${open ? ` ${open} of ${record.answers.length} questions have no answer.` : ''}`;
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
