// What the class got wrong, question by question (summarizeQuestions.js gives the numbers): the
// share right; for a choice, how many chose each option, each wrong one with the misconception its
// explanation states; for a number, how the answers sit against the computed value on a log scale
// (a slip by a factor stands as a peak at that factor, whatever each student's numbers) and the
// question's named slips; for a prediction, predicted minus true angle. Bars are elements with their
// count as text, in the page's colours, so they read on a projector and to a screen reader; no name
// appears anywhere, so a card can be shown to the class as it is.
import { button, el } from '../../../ui/el.js';
import { fixed } from '../../../ui/format.js';
import { setSubscripted } from '../../../ui/subscripts.js';
import { KIND_NAMES, questionById } from '../../questions.js';
import { panelEntry } from '../../../panels/manifest.js';
import { panelTitle } from '../../../panels/panelText.js';

const CARDS_PER_TASK = 8;
const nextTask = () => new Promise((resolve) => { setTimeout(resolve, 0); });
const percent = (share) => (share === null ? '—' : `${Math.round(100 * share)} %`);
const students = (n) => `${n} student${n === 1 ? '' : 's'}`;

/** A horizontal bar with its label and count: a list item, so it is read as "label: n students". */
function barItem(label, count, total, className = '') {
  const item = el('li', `hw-bar ${className}`);
  const text = el('span', 'hw-bar-label');
  setSubscripted(text, label);
  const track = el('span', 'hw-bar-track');
  const fill = el('span', 'hw-bar-fill');
  fill.style.setProperty('--share', String(total ? count / total : 0));
  track.append(fill);
  track.setAttribute('aria-hidden', 'true');
  item.append(text, track, el('span', 'hw-bar-count', `: ${students(count)}`));
  return item;
}

/** A bin's answers in words: how many, and how many of them right and wrong. */
function answersText(bin) {
  if (bin.right && bin.wrong) return `${students(bin.count)}: ${bin.right} right, ${bin.wrong} wrong`;
  return bin.right ? `${students(bin.right)}, right` : `${students(bin.wrong)}${bin.wrong ? ', wrong' : ''}`;
}

/**
 * Columns over bins ({ lo, hi, count, right, wrong }), cut to the span that holds answers (and 0),
 * each with its count said; a column's right answers in green under its wrong ones in red, so every
 * answer is seen where it is. `tick(bin)` gives a label under a column or ''.
 */
function columns(bins, { caption, binText, tick }) {
  const figure = el('figure', 'hw-histogram');
  const used = bins.map((b, i) => (b.count > 0 || (b.lo <= 0 && b.hi > 0) ? i : -1)).filter((i) => i >= 0);
  const from = Math.max(0, Math.min(...used) - 1);
  const to = Math.min(bins.length - 1, Math.max(...used) + 1);
  const most = Math.max(1, ...bins.map((b) => b.count));
  const list = el('ol', 'hw-columns');
  for (const bin of bins.slice(from, to + 1)) {
    const item = el('li', `hw-column${bin.lo <= 0 && bin.hi > 0 ? ' hw-column-zero' : ''}`);
    for (const [part, count] of [['hw-column-wrong', bin.wrong], ['hw-column-right', bin.right]]) {
      const bar = el('span', `hw-column-bar ${part}`);
      bar.style.setProperty('--share', String(count / most));
      bar.setAttribute('aria-hidden', 'true');
      item.append(bar);
    }
    const label = tick(bin);
    item.append(el('span', 'hw-column-tick', label));
    item.append(el('span', 'sr-only', `${binText(bin)}: ${answersText(bin)}`));
    if (bin.count === 0) item.setAttribute('aria-hidden', 'true');
    item.title = `${binText(bin)}: ${answersText(bin)}`;
    list.append(item);
  }
  figure.append(list, el('figcaption', null, caption));
  return figure;
}

const ratioText = (x) => {
  const q = 10 ** x;
  const shown = (x) => (x < 10 ? fixed(x, 2) : x.toPrecision(3));
  return q >= 1 ? `×${shown(q)}` : `÷${shown(1 / q)}`;
};

function numericParts(summary) {
  const { ratio } = summary;
  const parts = [];
  const answered = summary.right + summary.wrong;
  if (!answered) return [el('p', null, 'No student answered.')];
  const named = new Map(ratio.labels.map((l) => [l.at, l.text.split(':')[0]]));
  const tick = (bin) => {
    if (bin.lo <= 0 && bin.hi > 0) return '×1';
    for (const [at, text] of named) if (at >= bin.lo && at < bin.hi) return text;
    return '';
  };
  parts.push(columns(ratio.bins, {
    caption: 'Each answer divided by the value computed for that student, on a log scale: right answers (green) stand at ×1, '
      + 'a slip by a factor as a column at that factor.',
    binText: (bin) => `${ratioText(bin.lo)} to ${ratioText(bin.hi)}`, tick,
  }));
  const outsideBins = [
    ratio.below + ratio.above > 0 ? `${students(ratio.below + ratio.above)} off by more than a factor of 1000` : '',
    ratio.opposite ? `${students(ratio.opposite)} with the opposite sign` : '',
    ratio.zero ? `${students(ratio.zero)} answered 0` : '',
    ratio.noRatio ? `${students(ratio.noRatio)} where the computed value is 0 (no ratio to plot)` : '',
  ].filter(Boolean);
  if (outsideBins.length) parts.push(el('p', 'hw-meta', `Not in the plot: ${outsideBins.join('; ')}.`));
  // Each wrong answer under one slip at most: a named slip, else a factor, else where it lies.
  const { elsewhere } = summary;
  const slips = [
    ...(summary.slips ?? []).filter((s) => s.count > 0).map((s) => `${s.label}: ${students(s.count)}`),
    ...ratio.labels.filter((l) => l.count > 0).map((l) => `${l.text}: ${students(l.count)}`),
    elsewhere.zero ? `0: ${students(elsewhere.zero)}` : '',
    elsewhere.opposite ? `the opposite sign: ${students(elsewhere.opposite)}` : '',
    elsewhere.far ? `more than a factor of 1000 off: ${students(elsewhere.far)}` : '',
  ].filter(Boolean);
  const list = el('ul', 'hw-slips');
  for (const text of slips) list.append(el('li', null, text));
  if (list.childElementCount) parts.push(el('p', 'hw-slips-title', 'Slips seen (each wrong answer under one at most):'), list);
  return parts;
}

function predictParts(summary) {
  if (!(summary.right + summary.wrong)) return [el('p', null, 'No student predicted.')];
  const { step, bins } = summary.offset;
  const signed = (x) => `${x > 0 ? '+' : x < 0 ? '−' : ''}${Math.abs(x)}°`;
  return [columns(bins, {
    caption: `Predicted minus true angle, in ${step}° steps: to the right, predictions too large.`,
    binText: (bin) => `${signed(bin.lo)} to ${signed(bin.hi)}`,
    tick: (bin) => { const mid = (bin.lo + bin.hi) / 2; return mid % 15 === 0 ? signed(mid) : ''; },
  })];
}

function choiceParts(summary) {
  const list = el('ol', 'hw-bars');
  const answered = summary.right + summary.wrong;
  for (const option of summary.options) {
    const wrongOnly = option.chosenWhenRight === 0 && option.chosen > 0;
    const item = barItem(option.text, option.chosen, answered, wrongOnly ? 'hw-bar-wrong' : option.chosenWhenRight ? 'hw-bar-right' : '');
    if (option.chosenWhenWrong) {
      const why = el('span', 'hw-bar-why');
      // The explanation of the numbers in the prompt above; an option that holds for them was wrong only for others'.
      setSubscripted(why, option.why ? `Why it is wrong: ${option.why}`
        : `Right for the numbers above; wrong for the ${students(option.chosenWhenWrong)} who chose it with other numbers.`);
      item.append(why);
    }
    list.append(item);
  }
  return [list];
}

/** The prompt of the card's one instance: the same for all (a class seed, or a question without numbers), else one student's. */
function promptText(question, { params, sameForAll }) {
  const text = question.prompt(params);
  if (sameForAll) return text;
  return `${text} (Numbers differ from student to student; these are one student's${question.kind === 'choice'
    ? ', and so are the options and explanations below' : ''}.)`;
}

/**
 * A card per question of the view (buildClassView's result), made a few per task. onShow(card,
 * index): show one card to the class. Resolves to the element holding the cards.
 */
export async function questionSummaries(view, { onShow }) {
  const holder = el('div', 'hw-class-questions');
  for (const [i, summary] of view.summary.entries()) {
    if (i % CARDS_PER_TASK === 0) await nextTask();
    const question = questionById(summary.question);
    const card = el('section', 'hw-class-question');
    const heading = el('h4', 'hw-heading');
    heading.id = `class-q${i + 1}`;
    card.setAttribute('aria-labelledby', heading.id);
    const panel = el('span', 'hw-panel-name');
    setSubscripted(panel, panelEntry(question.panel) ? panelTitle(question.panel) : question.panel);
    heading.append(el('span', null, `Question ${i + 1}`), el('span', 'hw-kind', KIND_NAMES[question.kind]), panel);
    card.append(heading);
    if (summary.shown) {
      const prompt = el('p', 'hw-prompt');
      setSubscripted(prompt, promptText(question, summary.shown));
      card.append(prompt);
    }
    card.append(el('p', 'hw-share', `${percent(summary.shareRight)} right: ${summary.right} right, ${summary.wrong} wrong, `
      + `${summary.unanswered} unanswered, of ${students(summary.students)}.`));
    if (summary.kind === 'choice') card.append(...choiceParts(summary));
    else if (summary.kind === 'numeric') card.append(...numericParts(summary));
    else card.append(...predictParts(summary));
    const show = button('Show the class', 'hw-show-class');
    show.setAttribute('aria-label', `Show question ${i + 1} to the class (no names)`);
    show.addEventListener('click', () => onShow(card, i, show));
    card.append(show);
    holder.append(card);
  }
  return holder;
}
