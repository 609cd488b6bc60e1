// One question of a sheet, on its panel: the prompt, the way to answer it (a typed number, a
// prediction marker, options), the result once it may be shown, and the panel itself, started
// from the question's state. A prediction is committed before the panel appears, so the panel
// cannot give it away; the prediction stays drawn next to the truth. In lecture mode nothing is
// judged on screen until the lecturer reveals the question.
import { el } from '../../ui/el.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { panelEntry } from '../../panels/manifest.js';
import { gradeAnswer, trueOption } from '../gradeAnswer.js';
import { createPredictFigure } from './createPredictFigure.js';
import { KIND_NAMES, formatTolerance, formatValue } from './formatAnswer.js';

const UNIT_HINTS = { deg: 'in degrees, e.g. 41.8 or 41.8°', fraction: 'a fraction, e.g. 0.042 or 4.2 %' };

/** The panel, in a frame of the embed page started from `state` (values the panel checks itself). */
function panelFrame(panelId, state) {
  const url = new URL('./embed.html', window.location.href);
  url.searchParams.set('panel', panelId);
  for (const [key, value] of Object.entries(state)) url.searchParams.set(key, String(value));
  const frame = el('iframe', 'hw-frame');
  frame.src = url.toString();
  frame.loading = 'lazy';
  frame.title = `Fresnel Lab: ${panelEntry(panelId).title}`;
  frame.allow = 'fullscreen; clipboard-write';
  // The embed says how tall its content is (message API `size`): the frame fits it, no inner scroll.
  window.addEventListener('message', (event) => {
    if (event.source !== frame.contentWindow || event.data?.type !== 'fresnel-lab:size') return;
    const height = Number(event.data.height);
    if (Number.isFinite(height)) frame.style.height = `${Math.min(3000, Math.max(160, Math.ceil(height) + 2))}px`;
  });
  return frame;
}

/**
 * number: 1-based position; item: { question, state? } of the sheet; question and params: the
 * question and its seeded parameters; saved: the stored answer or null; lecture(): whether lecture
 * mode is on; onAnswer(answer): the answer changed (to be stored).
 * Returns { element, answer(), reveal(), refresh() }.
 */
export function buildQuestionCard({ number, item, question, params, saved, lecture, onAnswer }) {
  const entry = panelEntry(question.panel);
  const element = el('article', `hw-item hw-${question.kind}`);
  element.id = `question-${number}`;
  const heading = el('h2', 'hw-heading');
  heading.id = `question-${number}-title`;
  heading.append(el('span', 'hw-number', `Question ${number}`), el('span', 'hw-kind', KIND_NAMES[question.kind]));
  const where = el('span', 'hw-panel-name');
  setSubscripted(where, entry.title);
  heading.append(where);
  element.setAttribute('aria-labelledby', heading.id);
  const prompt = el('p', 'hw-prompt');
  prompt.id = `question-${number}-prompt`;
  setSubscripted(prompt, question.prompt(params));
  const answerBox = el('div', 'hw-answer');
  const result = el('div', 'hw-result');
  result.setAttribute('role', 'status');
  result.setAttribute('aria-live', 'polite');
  const panelBox = el('div', 'hw-panel');
  element.append(heading, prompt, answerBox, result, panelBox);

  let answer = saved;
  let revealed = false; // by the lecturer, in lecture mode
  const state = { ...(item.state ?? {}), ...question.state(params) }; // the question's own values win
  const showPanel = () => { if (!panelBox.firstChild) panelBox.append(panelFrame(question.panel, state)); };
  const judged = () => (lecture() ? revealed : answer !== null);

  let figure = null;
  let input = null;
  const options = [];
  const commit = el('button', 'hw-commit');
  commit.type = 'button';

  if (question.kind === 'numeric') {
    const label = el('label', 'hw-field');
    label.append(el('span', null, `Your answer (${UNIT_HINTS[question.unit] ?? 'a number'})`));
    input = el('input');
    input.type = 'text';
    input.inputMode = 'decimal';
    input.autocomplete = 'off';
    input.setAttribute('aria-describedby', prompt.id);
    input.value = answer ?? '';
    label.append(input);
    commit.textContent = 'Check';
    const submit = () => { answer = input.value; onAnswer(answer); render(); };
    commit.addEventListener('click', submit);
    input.addEventListener('keydown', (event) => { if (event.key === 'Enter') submit(); });
    answerBox.append(label, commit);
  } else if (question.kind === 'predict') {
    figure = createPredictFigure({ label: `Your prediction for question ${number}, θ in degrees` });
    if (answer !== null) figure.setValue(answer);
    commit.textContent = 'Commit prediction';
    commit.addEventListener('click', () => { answer = figure.value(); onAnswer(answer); render(); });
    answerBox.append(figure.element, commit);
  } else {
    const group = el('fieldset', 'hw-options');
    group.append(el('legend', 'sr-only', `Options for question ${number}`));
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
    }
    commit.textContent = 'Check';
    commit.addEventListener('click', () => {
      const chosen = options.find((o) => o.radio.checked);
      if (!chosen) { result.textContent = 'Choose an option first.'; return; }
      answer = chosen.option.id;
      onAnswer(answer);
      render();
    });
    answerBox.append(group, commit);
  }

  const say = (kind, text) => {
    result.className = `hw-result hw-${kind}`;
    result.textContent = text;
  };

  function render() {
    const graded = answer === null ? null : gradeAnswer(question, params, answer);
    if (question.kind === 'predict') {
      if (answer !== null) { figure.setValue(answer); figure.lock(); commit.disabled = true; }
      if (judged()) {
        figure.lock();
        commit.disabled = true;
        figure.showTruth({ curve: question.curve(params), truth: question.expected(params) });
        showPanel();
      }
    } else {
      showPanel();
    }
    if (!judged()) {
      say('waiting', answer === null ? '' : 'Answer saved. The answer is shown when the lecturer reveals it.');
      return;
    }
    if (question.kind === 'choice') {
      const right = trueOption(question, params);
      const all = revealed || graded?.correct;
      for (const o of options) {
        o.label.classList.toggle('hw-chosen', o.option.id === answer);
        o.label.classList.toggle('hw-true', all && o.option.id === right.id);
        setSubscripted(o.why, all || o.option.id === answer ? o.option.why(params) : '');
      }
      if (!graded) say('shown', `The answer: “${right.text(params)}”`);
      else say(graded.correct ? 'right' : 'wrong', graded.correct ? 'Right.' : 'Not this one: see why under your choice, and try another.');
      return;
    }
    const expected = question.expected(params);
    const truth = `The computed answer is ${formatValue(question, expected)} (checked within ${formatTolerance(question)}).`;
    if (!graded) { say('shown', truth); return; }
    if (!graded.answered) { say('wrong', graded.explanation); return; }
    if (graded.correct) say('right', `Right. ${truth}`);
    else if (question.kind === 'predict' || revealed) say('wrong', `${question.kind === 'predict' ? 'Off' : 'Not within the tolerance'}: yours ${formatValue(question, graded.value)}. ${truth}`);
    else say('wrong', `${graded.explanation} Try again.`);
  }
  render();

  return {
    element,
    answer: () => answer,
    reveal() { revealed = true; render(); },
    refresh: render,
    focus: () => (figure ? figure.focus() : input ? input.focus() : options[0]?.radio.focus()),
  };
}
