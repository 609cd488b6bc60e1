// @ts-check
// What the class got wrong, question by question (summarizeQuestions.js gives the numbers): the
// share right; for a choice, how many chose each option, each wrong one with the misconception its
// explanation states; for a number, how the answers sit against the computed value on a log scale
// (a slip by a factor stands as a peak at that factor, whatever each student's numbers) and the
// question's named slips; for a prediction, predicted minus true angle. Bars are elements with their
// count as text, in the page's colours, so they read on a projector and to a screen reader; no name
// appears anywhere, so a card can be shown to the class as it is.
import { button, el } from '../../../ui/el.js';
import { fixed, precise } from '../../../ui/format.js';
import { setSubscripted } from '../../../ui/subscripts.js';
import { kindName, knownQuestion } from '../../questions.js';
import { panelEntry } from '../../../panels/manifest.js';
import { panelTitle } from '../../../panels/panelText.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../../i18n/messages.js';

const t = messages('class', english);

/** @typedef {import('../../class/summarizeQuestions.js').Bin} Bin */
/** @typedef {import('../../class/summarizeQuestions.js').QuestionSummary} QuestionSummary */

const CARDS_PER_TASK = 8;
const nextTask = () => new Promise((resolve) => { setTimeout(resolve, 0); });
const percent = (/** @type {number | null} */ share) => (share === null ? '—' : t('summary.percent', { percent: fixed(100 * share, 0) }));
/** A count for a plural message: the number that picks the form, and the number shown. */
const many = (/** @type {number} */ count) => ({ count, n: fixed(count, 0) });

/**
 * A horizontal bar with its label and count: a list item, so it is read as "label: n students".
 * @param {string} label
 * @param {number} count
 * @param {number} total
 */
function barItem(label, count, total, className = '') {
  const item = el('li', `hw-bar ${className}`);
  const text = el('span', 'hw-bar-label');
  setSubscripted(text, label);
  const track = el('span', 'hw-bar-track');
  const fill = el('span', 'hw-bar-fill');
  fill.style.setProperty('--share', String(total ? count / total : 0));
  track.append(fill);
  track.setAttribute('aria-hidden', 'true');
  item.append(text, track, el('span', 'hw-bar-count', t('summary.barCount', many(count))));
  return item;
}

/**
 * A bin's answers in words: how many, and how many of them right and wrong.
 * @param {Bin} bin
 */
function answersText(bin) {
  if (bin.right && bin.wrong) return t('summary.binBoth', { ...many(bin.count), right: bin.right, wrong: bin.wrong });
  return bin.right ? t('summary.binRight', many(bin.right)) : t('summary.binWrong', many(bin.wrong));
}

/**
 * Columns over bins ({ lo, hi, count, right, wrong }), cut to the span that holds answers (and 0),
 * each with its count said; a column's right answers in green under its wrong ones in red, so every
 * answer is seen where it is. `tick(bin)` gives a label under a column or ''.
 * @param {Bin[]} bins
 * @param {{ caption: string, binText: (bin: Bin) => string, tick: (bin: Bin) => string }} words
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
    for (const [part, count] of /** @type {[string, number][]} */ ([['hw-column-wrong', bin.wrong], ['hw-column-right', bin.right]])) {
      const bar = el('span', `hw-column-bar ${part}`);
      bar.style.setProperty('--share', String(count / most));
      bar.setAttribute('aria-hidden', 'true');
      item.append(bar);
    }
    const label = tick(bin);
    item.append(el('span', 'hw-column-tick', label));
    const says = t('summary.binSays', { bin: binText(bin), answers: answersText(bin) });
    item.append(el('span', 'sr-only', says));
    if (bin.count === 0) item.setAttribute('aria-hidden', 'true');
    item.title = says;
    list.append(item);
  }
  figure.append(list, el('figcaption', null, caption));
  return figure;
}

const ratioText = (/** @type {number} */ x) => {
  const q = 10 ** x;
  const shown = (/** @type {number} */ x) => (x < 10 ? fixed(x, 2) : precise(x, 3));
  return q >= 1 ? `×${shown(q)}` : `÷${shown(1 / q)}`;
};

/** @param {import('../../class/summarizeQuestions.js').NumericSummary} summary */
function numericParts(summary) {
  const { ratio } = summary;
  /** @type {HTMLElement[]} */
  const parts = [];
  const answered = summary.right + summary.wrong;
  if (!answered) return [el('p', null, t('summary.noneAnswered'))];
  const named = new Map(ratio.labels.map((l) => [l.at, l.short]));
  const tick = (/** @type {Bin} */ bin) => {
    if (bin.lo <= 0 && bin.hi > 0) return t('summary.one');
    for (const [at, text] of named) if (at >= bin.lo && at < bin.hi) return text;
    return '';
  };
  parts.push(columns(ratio.bins, {
    caption: t('summary.ratioCaption'),
    binText: (bin) => t('summary.range', { from: ratioText(bin.lo), to: ratioText(bin.hi) }), tick,
  }));
  const outsideBins = [
    ratio.below + ratio.above > 0 ? t('summary.outFar', many(ratio.below + ratio.above)) : '',
    ratio.opposite ? t('summary.outOpposite', many(ratio.opposite)) : '',
    ratio.zero ? t('summary.outZero', many(ratio.zero)) : '',
    ratio.noRatio ? t('summary.outNoRatio', many(ratio.noRatio)) : '',
  ].filter(Boolean);
  if (outsideBins.length) parts.push(el('p', 'hw-meta', t('summary.notInPlot', { list: outsideBins.join(t('summary.listSeparator')) })));
  // Each wrong answer under one slip at most: a named slip, else a factor, else where it lies.
  const { elsewhere } = summary;
  const slips = [
    ...(summary.slips ?? []).filter((s) => s.count > 0).map((s) => t('summary.slip', { slip: s.label, ...many(s.count) })),
    ...ratio.labels.filter((l) => l.count > 0).map((l) => t('summary.slip', { slip: l.text, ...many(l.count) })),
    elsewhere.zero ? t('summary.slipZero', many(elsewhere.zero)) : '',
    elsewhere.opposite ? t('summary.slipOpposite', many(elsewhere.opposite)) : '',
    elsewhere.far ? t('summary.slipFar', many(elsewhere.far)) : '',
  ].filter(Boolean);
  const list = el('ul', 'hw-slips');
  for (const text of slips) list.append(el('li', null, text));
  if (list.childElementCount) parts.push(el('p', 'hw-slips-title', t('summary.slipsTitle')), list);
  return parts;
}

/** @param {import('../../class/summarizeQuestions.js').PredictSummary} summary */
function predictParts(summary) {
  if (!(summary.right + summary.wrong)) return [el('p', null, t('summary.nonePredicted'))];
  const { step, bins } = summary.offset;
  const signed = (/** @type {number} */ x) => `${x > 0 ? '+' : x < 0 ? '−' : ''}${fixed(Math.abs(x), Number.isInteger(x) ? 0 : 1)}°`;
  return [columns(bins, {
    caption: t('summary.offsetCaption', { step }),
    binText: (bin) => t('summary.range', { from: signed(bin.lo), to: signed(bin.hi) }),
    tick: (bin) => { const mid = (bin.lo + bin.hi) / 2; return mid % 15 === 0 ? signed(mid) : ''; },
  })];
}

/** @param {import('../../class/summarizeQuestions.js').ChoiceSummary} summary */
function choiceParts(summary) {
  const list = el('ol', 'hw-bars');
  const answered = summary.right + summary.wrong;
  for (const option of summary.options) {
    const wrongOnly = option.chosenWhenRight === 0 && option.chosen > 0;
    const item = barItem(option.text, option.chosen, answered, wrongOnly ? 'hw-bar-wrong' : option.chosenWhenRight ? 'hw-bar-right' : '');
    if (option.chosenWhenWrong) {
      const why = el('span', 'hw-bar-why');
      // The explanation of the numbers in the prompt above; an option that holds for them was wrong only for others'.
      setSubscripted(why, option.why ? t('summary.whyWrong', { why: option.why })
        : t('summary.rightForOthers', many(option.chosenWhenWrong)));
      item.append(why);
    }
    list.append(item);
  }
  return [list];
}

/**
 * The prompt of the card's one instance: the same for all (a class seed, or a question without numbers), else one student's.
 * @param {import('../../questions.js').Question} question
 * @param {{ params: unknown, sameForAll: boolean }} shown
 */
function promptText(question, { params, sameForAll }) {
  const text = question.prompt(params);
  if (sameForAll) return text;
  return t('summary.oneStudent', { prompt: text, choice: question.kind === 'choice' ? 'yes' : 'no' });
}

/**
 * A card per question of the view (buildClassView's result), made a few per task. onShow(card,
 * index): show one card to the class. Resolves to the element holding the cards.
 * @param {{ summary: QuestionSummary[] }} view
 * @param {{ onShow: (card: HTMLElement, index: number, from: HTMLElement) => void }} options
 */
export async function questionSummaries(view, { onShow }) {
  const holder = el('div', 'hw-class-questions');
  for (const [i, summary] of view.summary.entries()) {
    if (i % CARDS_PER_TASK === 0) await nextTask();
    const question = knownQuestion(summary.question);
    const card = el('section', 'hw-class-question');
    const heading = el('h4', 'hw-heading');
    heading.id = `class-q${i + 1}`;
    card.setAttribute('aria-labelledby', heading.id);
    const panel = el('span', 'hw-panel-name');
    setSubscripted(panel, panelEntry(question.panel) ? panelTitle(question.panel) : question.panel);
    heading.append(el('span', null, t('summary.question', { number: i + 1 })), el('span', 'hw-kind', kindName(question.kind)), panel);
    card.append(heading);
    if (summary.shown) {
      const prompt = el('p', 'hw-prompt');
      setSubscripted(prompt, promptText(question, summary.shown));
      card.append(prompt);
    }
    card.append(el('p', 'hw-share', t('summary.share', {
      share: percent(summary.shareRight), right: summary.right, wrong: summary.wrong, unanswered: summary.unanswered,
      students: summary.students, studentsN: fixed(summary.students, 0),
    })));
    if (summary.kind === 'choice') card.append(...choiceParts(summary));
    else if (summary.kind === 'numeric') card.append(...numericParts(summary));
    else card.append(...predictParts(summary));
    const show = button(t('summary.show'), 'hw-show-class');
    show.setAttribute('aria-label', t('summary.showLabel', { number: i + 1 }));
    show.addEventListener('click', () => onShow(card, i, show));
    card.append(show);
    holder.append(card);
  }
  return holder;
}
