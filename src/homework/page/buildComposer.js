// The lecturer's composer: a title, how answers are revealed, an optional seed shared by the
// class, and the questions, grouped by panel in lecture order, each with an optional start state
// (a link copied from the panel). The sheet is read back by readSheet as it is built, so what is
// offered as a link or a file is exactly what a student's page will accept.
import { el } from '../../ui/el.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { PANELS } from '../../panels/manifest.js';
import { copyText, downloadBlob, downloadText } from '../../host/exporters.js';
import { fileSlug } from '../../ui/format.js';
import { KIND_NAMES, QUESTIONS } from '../questions.js';
import { questionParams } from '../gradeAnswer.js';
import { readSheet } from '../readSheet.js';
import { readStartState } from '../readStartState.js';
import { sheetToCode } from '../sheetCodes.js';
import { buildScormPackage } from './buildScormPackage.js';
import { button, field, titledSection } from './formParts.js';
import { panelTitle } from '../../panels/panelText.js';

/** The page's address for a sheet: homework.html?sheet=CODE. */
export function sheetUrl(sheet) {
  const url = new URL('./homework.html', window.location.href);
  url.search = '';
  url.searchParams.set('sheet', sheetToCode(sheet));
  return url.toString();
}

export function buildComposer(root) {
  const { section, heading } = titledSection('hw-composer', 'composer-title', 'Compose a sheet');
  const title = el('input');
  title.type = 'text';
  title.value = 'Fresnel reflection: homework';
  title.maxLength = 200;
  const reveal = el('select');
  reveal.add(new Option('after each answer (homework)', 'after-answer'));
  reveal.add(new Option('when the lecturer reveals them (in class)', 'lecturer'));
  const seed = el('input');
  seed.type = 'text';
  seed.maxLength = 64;
  seed.placeholder = 'empty: each student gets their own numbers';
  section.append(heading, field('Title', title), field('Answers are shown', reveal), field('One seed for the whole '
    + 'class (optional)', seed));

  const picks = [];
  for (const panel of PANELS) {
    const questions = QUESTIONS.filter((q) => q.panel === panel.id);
    if (!questions.length) continue;
    const group = el('fieldset', 'hw-pick-group');
    const legend = el('legend');
    setSubscripted(legend, panelTitle(panel.id));
    group.append(legend);
    for (const question of questions) {
      const row = el('div', 'hw-pick');
      const box = el('input');
      box.type = 'checkbox';
      box.id = `pick-${question.id}`;
      const label = el('label');
      label.htmlFor = box.id;
      const text = el('span');
      setSubscripted(text, question.prompt(questionParams(question, 'example')));
      label.append(el('span', 'hw-kind', KIND_NAMES[question.kind]), ' ', text);
      const state = el('input');
      state.type = 'text';
      state.placeholder = 'a link copied from the panel, or key=value&…';
      const stateLabel = field('Start state (optional)', state, 'hw-field hw-pick-state');
      stateLabel.hidden = true;
      const note = el('span', 'hw-pick-note');
      note.setAttribute('aria-live', 'polite');
      stateLabel.append(note);
      box.addEventListener('change', () => { stateLabel.hidden = !box.checked; update(); });
      state.addEventListener('input', () => update());
      row.append(box, label, stateLabel);
      group.append(row);
      picks.push({ question, box, state, note });
    }
    section.append(group);
  }

  const out = el('div', 'hw-composer-out');
  const problems = el('div', 'hw-problems');
  problems.setAttribute('role', 'status');
  const link = el('input');
  link.type = 'text';
  link.readOnly = true;
  const copy = button('Copy the link');
  const save = button('Save the sheet as a file');
  const open = el('a', 'hw-open', 'Open the sheet');
  const scorm = button('Save for an LMS (SCORM 1.2 zip)');
  out.append(problems, field('Link for students', link), copy, save, scorm, open);
  section.append(out);
  root.append(section);

  let current = null;
  function update() {
    const itemProblems = [];
    const items = picks.filter((p) => p.box.checked).map(({ question, state, note }, i) => {
      const read = readStartState(state.value, question.panel);
      if (!read.ok) itemProblems.push(`Question ${i + 1} (${panelTitle(question.panel)}): ${read.problem}`);
      // The question's own values win over a start state (its numbers depend on them): say which.
      const own = Object.keys(question.state(questionParams(question, 'example')));
      const overridden = Object.keys(read.state ?? {}).filter((k) => own.includes(k));
      note.textContent = overridden.length ? `Set by the question itself, so not taken from here: ${overridden.join(', ')}.` : '';
      return Object.keys(read.state ?? {}).length ? { question: question.id, state: read.state } : { question: question.id };
    });
    const draft = {
      version: 1, title: title.value.trim(), reveal: reveal.value, items, ...(seed.value.trim() ? { seed: seed.value.trim() } : {}),
    };
    const read = readSheet(draft);
    const all = items.length ? [...itemProblems, ...(read.ok ? [] : read.problems)] : ['Pick at least one question.'];
    current = all.length ? null : read.sheet;
    problems.replaceChildren(...all.map((p) => el('p', 'hw-problem', p)));
    link.value = current ? sheetUrl(current) : '';
    for (const control of [copy, save, scorm]) control.disabled = !current;
    if (current) open.href = link.value;
    else open.removeAttribute('href');
    open.setAttribute('aria-disabled', String(!current));
  }
  for (const control of [title, seed]) control.addEventListener('input', update);
  reveal.addEventListener('change', update);
  copy.addEventListener('click', async () => {
    link.select();
    problems.replaceChildren(el('p', null, (await copyText(link.value)) ? 'The link is copied.' : 'Copying was refused here: '
      + 'the link is selected, press Ctrl+C (⌘C).'));
  });
  save.addEventListener('click', () => {
    if (current) downloadText('fresnel-lab-sheet.json', `${JSON.stringify(current, null, 2)}\n`, 'application/json');
  });
  scorm.addEventListener('click', async () => {
    if (!current) return;
    const sheet = current;
    scorm.disabled = true;
    problems.replaceChildren(el('p', null, 'Making the package…'));
    try {
      const blob = await buildScormPackage(sheet);
      downloadBlob(`fresnel-lab-${fileSlug(sheet.title)}-scorm12.zip`, blob);
      problems.replaceChildren(el('p', null, `The package is saved (${Math.round(blob.size / 1024)} kB): `
        + `import it into the LMS as a SCORM package; the score of each hand-in goes to its gradebook.`));
    } catch (error) {
      problems.replaceChildren(el('p', 'hw-problem', error.message));
    } finally {
      scorm.disabled = !current;
    }
  });
  update();
  return { pick: (id) => picks.find((p) => p.question.id === id)?.box, update };
}
