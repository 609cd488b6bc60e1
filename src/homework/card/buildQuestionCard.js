// @ts-check
// One question of a sheet, on its panel: the prompt, the way to answer it (a typed number, a
// prediction marker, options), the result once it may be shown, and the panel itself, started
// from the question's state. A prediction is committed before the panel appears, so the panel
// cannot give it away; the prediction stays drawn next to the truth. In lecture mode nothing is
// judged on screen until the lecturer reveals the question; revealed, it takes no more answers.
// The homework page and a composed lecture both ask it; its styles are questionCard.css.
import { button, el } from '../../ui/el.js';
import { angle } from '../../ui/format.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { embedLink } from '../../host/embedLink.js';
import { panelSchema } from '../../panels/panelSchema.js';
import { kindName } from '../questions.js';
import { MAX_TYPED, gradeAnswer, trueOption } from '../gradeAnswer.js';
import { formatTolerance, formatValue } from '../formatAnswer.js';
import { createPredictFigure } from './createPredictFigure.js';
import './questionCard.css';
import { watchPanelFrame } from '../../ui/watchPanelFrame.js';
import { showNotice } from '../../host/showNotice.js';
import { field } from '../../ui/formParts.js';
import { panelTitle } from '../../panels/panelText.js';
import english from 'virtual:messages/en/homework';
import questionWords from 'virtual:messages/en/questions';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);
const tq = messages('questions', questionWords);

/**
 * A question's card: its answer so far, the tries it took, whether the lecturer revealed it.
 * @typedef {{ element: HTMLElement, answer: () => number | string | null, attempts: () => number, revealed: () => boolean,
 *   reveal: () => void, refresh: () => void }} QuestionCard
 */

/**
 * The panel in a frame of the embed page, started from `state`: its link written as every embed
 * link is (embedLink.js), the values through the panel's schema (a sheet's are checked by it).
 * @param {string} panelId
 * @param {import('../questionParts.js').PanelState} state
 */
function panelFrame(panelId, state) {
  const frame = el('iframe', 'hw-frame');
  frame.src = embedLink(new URL('./embed.html', window.location.href).href, { id: panelId, schema: panelSchema(panelId) ?? {} }, state);
  frame.loading = 'lazy';
  frame.title = t('card.frameTitle', { panel: panelTitle(panelId) });
  frame.allow = 'fullscreen; clipboard-write';
  return frame;
}

/**
 * number: 1-based position; item: { question, state? } of the sheet; question and params: the
 * question and its seeded parameters; saved: the stored answer (read by readAnswer) or null, and
 * attempts; lecture(): whether lecture mode is on; panelsAllowed(): false while a prediction on
 * the sheet is still open (any panel could give it away); onAnswer(answer): store it;
 * onFrame(frame): a panel's frame was made. Returns { element, answer(), attempts(), revealed(),
 * reveal(), refresh() }.
 * @param {{ number: number, item: { state?: import('../questionParts.js').PanelState }, question: import('../questions.js').Question,
 *   params: unknown, saved: number | string | null, attempts?: number, lecture: () => boolean, panelsAllowed: () => boolean,
 *   onAnswer: (answer: number | string | null) => void, onFrame: (frame: HTMLIFrameElement) => void }} card
 * @returns {QuestionCard}
 */
export function buildQuestionCard({
  number, item, question, params, saved, attempts: savedAttempts = 0, lecture, panelsAllowed, onAnswer, onFrame,
}) {
  const element = el('article', `hw-item hw-${question.kind}`);
  element.id = `question-${number}`;
  const heading = el('h2', 'hw-heading');
  heading.id = `question-${number}-title`;
  heading.append(el('span', 'hw-number', t('card.number', { number })), el('span', 'hw-kind', kindName(question.kind)));
  const where = el('span', 'hw-panel-name');
  setSubscripted(where, panelTitle(question.panel));
  heading.append(where);
  element.setAttribute('aria-labelledby', heading.id);
  const prompt = el('p', 'hw-prompt');
  prompt.id = `question-${number}-prompt`;
  setSubscripted(prompt, question.prompt(params));
  const answerBox = el('div', 'hw-answer');
  const result = el('div', 'hw-result');
  result.setAttribute('role', 'status');
  result.setAttribute('aria-live', 'polite');
  result.tabIndex = -1; // focus lands here after an answer, so the keyboard is not left on <body>
  const panelBox = el('div', 'hw-panel');
  element.append(heading, prompt, answerBox, result, panelBox);

  let answer = saved;
  let attempts = answer === null ? 0 : Math.max(1, savedAttempts);
  let revealed = false; // by the lecturer, in lecture mode
  const state = { ...(item.state ?? {}), ...question.state(params) }; // the question's own values win
  const judged = () => revealed || (!lecture() && answer !== null);
  const record = (/** @type {number | string | null} */ value) => {
    answer = value;
    attempts += 1;
    onAnswer(answer);
    render();
    result.focus();
  };

  /** @type {ReturnType<typeof createPredictFigure> | null} */
  let figure = null;
  /** @type {{ option: import('../questionParts.js').ChoiceOption<unknown>, radio: HTMLInputElement, label: HTMLElement,
   *   why: HTMLElement }[]} */
  const options = [];
  const commit = button('', 'hw-commit');
  /** @type {(HTMLButtonElement | HTMLInputElement)[]} */
  const controls = [commit];

  if (question.kind === 'numeric') {
    const input = el('input');
    input.type = 'text';
    input.inputMode = 'decimal';
    input.autocomplete = 'off';
    input.maxLength = MAX_TYPED;
    input.setAttribute('aria-describedby', prompt.id);
    input.value = String(answer ?? '');
    commit.textContent = t('card.check');
    const submit = () => record(input.value.trim() || null);
    commit.addEventListener('click', submit);
    input.addEventListener('keydown', (event) => { if (event.key === 'Enter') submit(); });
    answerBox.append(field(tq('answerLabel', { unit: question.unit ?? 'none' }), input), commit);
    controls.push(input);
  } else if (question.kind === 'predict') {
    // Any angle is a prediction, the marker's start included: the button names the one it commits.
    const name = (/** @type {number} */ value) => { commit.textContent = t('card.commit', { angle: angle(value, 1) }); };
    const axis = question.axis?.() ?? null;
    const made = createPredictFigure({
      label: t('card.predictionLabel', { number, axis: axis ?? 'θ' }),
      describedBy: prompt.id,
      ...(axis ? { axisTitle: axis, axisInText: question.axisInText?.() } : {}),
      onChange: name,
    });
    figure = made;
    if (typeof answer === 'number') made.setValue(answer); // a prediction's answer is an angle (readAnswer)
    name(made.value());
    commit.addEventListener('click', () => record(made.value()));
    answerBox.append(made.element, commit);
  } else {
    const group = el('fieldset', 'hw-options');
    group.setAttribute('aria-describedby', prompt.id);
    group.append(el('legend', 'sr-only', t('card.options', { number })));
    for (const option of question.options(params)) {
      const label = el('label', 'hw-option');
      const radio = el('input');
      radio.type = 'radio';
      radio.name = `question-${number}`;
      radio.value = option.id;
      radio.checked = answer === option.id;
      const text = el('span');
      setSubscripted(text, option.text(params));
      const why = el('span', 'hw-why');
      label.append(radio, text, why);
      group.append(label);
      options.push({ option, radio, label, why });
      controls.push(radio);
    }
    commit.textContent = t('card.check');
    commit.addEventListener('click', () => {
      const chosen = options.find((o) => o.radio.checked);
      if (!chosen) say('waiting', t('card.chooseFirst'));
      else record(chosen.option.id);
    });
    answerBox.append(group, commit);
  }

  /**
   * @param {string} kind
   * @param {string} text
   */
  function say(kind, text) {
    const className = `hw-result hw-${kind}`;
    if (result.className !== className) result.className = className;
    if (result.textContent !== text) result.textContent = text; // unchanged text is not announced again
  }

  let frameMissing = false; // its frame loaded something other than the embed page: not made again
  function showPanel() {
    if (panelBox.querySelector('iframe') || frameMissing) return;
    if (!panelsAllowed()) {
      if (!panelBox.firstChild) panelBox.append(el('p', 'hw-panel-waiting', t('card.panelWaits')));
      return;
    }
    const frame = panelFrame(question.panel, state);
    panelBox.replaceChildren(frame);
    watchPanelFrame(frame, () => {
      frame.remove(); // the browser's error page is no part of the lecture
      frameMissing = true;
      showNotice(panelBox, t('card.frameMissing'), [t('card.frameMissingWhy')], { kind: 'error' });
    });
    onFrame(frame);
  }

  /**
   * @param {import('../questions.js').ChoiceQuestion} question
   * @param {import('../gradeAnswer.js').Grade | null} graded
   */
  function renderChoice(question, graded) {
    const right = trueOption(question, params);
    const all = judged() && (revealed || graded?.correct);
    for (const o of options) {
      o.label.classList.toggle('hw-chosen', judged() && o.option.id === answer);
      o.label.classList.toggle('hw-true', all && o.option.id === right.id);
      setSubscripted(o.why, judged() && (all || o.option.id === answer) ? o.option.why(params) : '');
    }
    if (!judged()) return;
    if (!graded) say('shown', t('card.theAnswer', { answer: right.text(params) }));
    else if (graded.correct) say('right', t('card.right'));
    else say('wrong', revealed ? t('card.notThisOneRevealed') : t('card.notThisOne'));
  }

  function render() {
    const graded = answer === null ? null : gradeAnswer(question, params, answer);
    if (question.kind === 'predict' && figure) {
      if (answer !== null) {
        if (typeof answer === 'number') figure.setValue(answer); // a prediction's answer is an angle (readAnswer)
        figure.lock();
        commit.disabled = true;
      }
      if (judged()) {
        if (answer === null) figure.lock({ committed: false });
        commit.disabled = true;
        figure.showTruth({ curve: question.curve(params), truth: question.expected(params) });
      } else {
        figure.hideTruth();
      }
    }
    if (question.kind !== 'predict' || judged()) showPanel(); // a prediction's panel waits for its truth
    if (revealed) for (const control of controls) control.disabled = true; // the truth is out: no more answers
    if (question.kind === 'choice') renderChoice(question, graded);
    if (!judged()) {
      say('waiting', answer === null ? '' : t('card.saved'));
      return;
    }
    if (question.kind === 'choice') return;
    const truth = { value: formatValue(question, question.expected(params)), tolerance: formatTolerance(question) };
    if (!graded) say('shown', t(question.kind === 'predict' ? 'card.noPrediction' : 'card.truth', truth));
    else if (!graded.answered) say('wrong', graded.explanation);
    else if (graded.correct) say('right', t('card.rightTruth', truth));
    else if (question.kind === 'predict' || revealed) {
      const yours = formatValue(question, graded.value ?? NaN); // an answered value's grade has it (gradeAnswer.js)
      say('wrong', t(question.kind === 'predict' ? 'card.offTruth' : 'card.notWithinTruth', { ...truth, yours }));
    } else say('wrong', t('card.tryAgain', { explanation: graded.explanation }));
  }
  render();

  return {
    element,
    answer: () => answer,
    attempts: () => attempts,
    revealed: () => revealed,
    reveal() { revealed = true; render(); },
    refresh: render,
  };
}
