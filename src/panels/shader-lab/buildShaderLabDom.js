// The DOM of the shader lab: the exercise and its criteria (stated before any code is graded),
// the editor, the buttons, what the compiler or the page refused, the result of each criterion,
// the error summary, and the student's stability map beside the reference answer's.
import { button, el } from '../../ui/el.js';
import { createMapFigure } from '../shared/createMapFigure.js';
import '../shared/twinStage.css';
import english from 'virtual:messages/en/shader-lab';
import { messages } from '../../i18n/messages.js';

const t = messages('shader-lab', english);
const SIGNATURE_MARK = '\u0001'; // where the signature goes in the task's sentence

export function buildShaderLabDom(host) {
  const root = el('div', 'sl-panel st-panel');
  const task = el('div', 'sl-task');
  const title = el('h3', 'sl-title');
  const signature = el('p', 'sl-signature');
  const criteria = el('ol', 'sl-criteria');
  criteria.setAttribute('aria-label', t('criteria'));
  task.append(title, signature, criteria);
  const editor = el('div', 'sl-editor');
  const actions = el('div', 'sl-actions');
  const grade = button(t('grade'));
  const restart = button(t('startOver'));
  const reference = button(t('showReference'));
  actions.append(grade, restart, reference);
  const errors = el('ul', 'sl-errors');
  errors.setAttribute('aria-live', 'polite'); // said when it changes, not at every grade
  const summary = el('p', 'sl-summary');
  summary.setAttribute('aria-live', 'polite');
  const note = el('p', 'sl-note');
  const spheres = el('div', 'twin-stage sl-spheres');
  const spheresCanvas = el('canvas', 'twin-stage-canvas');
  spheresCanvas.setAttribute('role', 'img');
  const labels = el('div', 'twin-stage-labels');
  labels.append(el('span', null, t('yourFunction')), el('span', null, t('exactFunction')));
  const spheresMessage = el('p', 'sl-spheres-message');
  spheres.append(spheresCanvas, labels, spheresMessage);
  const maps = el('div', 'st-maps');
  const student = createMapFigure('student', { focusable: false }); // no probe here: not a tab stop
  const referenceMap = createMapFigure('reference', { focusable: false });
  maps.append(student.figure, referenceMap.figure);
  root.append(task, editor, actions, errors, summary, note, spheres, maps);
  host.append(root);

  return {
    root,
    editor,
    grade,
    restart,
    reference,
    maps,
    spheres,
    spheresCanvas,
    /** A sentence in place of the spheres (the code does not compile, no WebGL), or '' to show them. */
    setSpheresMessage(text) {
      spheresMessage.textContent = text;
      spheresMessage.hidden = !text;
      spheresCanvas.hidden = labels.hidden = Boolean(text);
      spheres.classList.toggle('sl-no-spheres', Boolean(text));
    },
    student,
    referenceMap,
    /** The exercise's title and signature, and its criteria: words, and the reason once graded. */
    setTask(exercise, rows) {
      title.textContent = exercise.title;
      // The sentence split where the signature goes, so a language may put the code anywhere in it.
      const [before, after = ''] = t('task', { signature: SIGNATURE_MARK }).split(SIGNATURE_MARK);
      signature.replaceChildren(before, el('code', null, exercise.signature), after);
      criteria.replaceChildren(...rows.map(({ label, precision, result, reason }) => {
        const item = el('li', `sl-criterion${result ? (result.pass ? ' sl-pass' : ' sl-fail') : ''}`);
        const state = t(result ? (result.pass ? 'passed' : 'failed') : 'notGraded');
        const named = precision === 'mediump' ? t('criterionMediump', { criterion: label }) : label;
        item.append(el('span', 'sl-state', state), ' ', el('span', null, named));
        if (result) item.append(el('span', 'sl-reason', reason));
        return item;
      }));
    },
    setErrors(list) {
      const texts = list.map(({ line, message }) => (line ? t('errorLine', { line: String(line), message }) : message));
      const shown = [...errors.children].map((li) => li.textContent);
      if (texts.join('\n') !== shown.join('\n')) errors.replaceChildren(...texts.map((t) => el('li', null, t)));
      errors.hidden = list.length === 0;
    },
    setSummary(text) { if (summary.textContent !== text) summary.textContent = text; },
    setNote(text) { note.textContent = text; note.hidden = !text; },
  };
}
