// @ts-check
// The lecturer's composer: a title, how answers are revealed, an optional seed shared by the
// class, and the questions, grouped by panel in lecture order, each with an optional start state
// (a link copied from the panel). The sheet is read back by readSheet as it is built, so what is
// offered as a link or a file is exactly what a student's page will accept. It carries the
// language the page is in, so that it opens in the language it was made in.
import { button, el } from '../../ui/el.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { PANELS } from '../../panels/manifest.js';
import { copyText, downloadBlob, downloadText } from '../../host/exporters.js';
import { fileSlug, grouped } from '../../ui/format.js';
import { QUESTIONS, kindName } from '../questions.js';
import { questionParams } from '../gradeAnswer.js';
import { readSheet } from '../readSheet.js';
import { readStartState } from '../readStartState.js';
import { sheetToCode } from '../sheetCodes.js';
import { buildScormPackage } from './buildScormPackage.js';
import { field, titledSection } from '../../ui/formParts.js';
import { panelTitle } from '../../panels/panelText.js';
import english from 'virtual:messages/en/homework';
import { currentLanguage, messages } from '../../i18n/messages.js';

const t = messages('homework', english);

/**
 * The page's address for a sheet: homework.html?sheet=CODE.
 * @param {import('../readSheet.js').Sheet} sheet
 */
export function sheetUrl(sheet) {
  const url = new URL('./homework.html', window.location.href);
  url.search = '';
  url.searchParams.set('sheet', sheetToCode(sheet));
  return url.toString();
}

/**
 * The composer's section in `root`: pick(id) gives a question's checkbox, update() reads the form again.
 * @param {Element} root
 */
export function buildComposer(root) {
  const { section, heading } = titledSection('hw-composer', 'composer-title', t('composer.title'));
  const title = el('input');
  title.type = 'text';
  title.value = t('composer.defaultTitle');
  title.maxLength = 200;
  const reveal = el('select');
  reveal.add(new Option(t('composer.revealAfterAnswer'), 'after-answer'));
  reveal.add(new Option(t('composer.revealLecturer'), 'lecturer'));
  const seed = el('input');
  seed.type = 'text';
  seed.maxLength = 64;
  seed.placeholder = t('composer.seedPlaceholder');
  section.append(heading, field(t('composer.sheetTitle'), title), field(t('composer.reveal'), reveal), field(t('composer.seed'), seed));

  /** @type {{ question: import('../questions.js').Question, box: HTMLInputElement, state: HTMLInputElement, note: HTMLElement }[]} */
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
      label.append(el('span', 'hw-kind', kindName(question.kind)), ' ', text);
      const state = el('input');
      state.type = 'text';
      state.placeholder = t('composer.statePlaceholder');
      const stateLabel = field(t('composer.state'), state, 'hw-pick-state');
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
  const copy = button(t('composer.copy'));
  const save = button(t('composer.save'));
  const open = el('a', 'hw-open', t('composer.open'));
  const scorm = button(t('composer.scorm'));
  out.append(problems, field(t('composer.link'), link), copy, save, scorm, open);
  section.append(out);
  root.append(section);

  /** @type {import('../readSheet.js').Sheet | null} */
  let current = null;
  function update() {
    /** @type {string[]} */
    const itemProblems = [];
    const items = picks.filter((p) => p.box.checked).map(({ question, state, note }, i) => {
      const read = readStartState(state.value, question.panel);
      if (!read.ok) {
        itemProblems.push(t('composer.itemProblem', { number: i + 1, panel: panelTitle(question.panel), problem: read.problem }));
      }
      const start = read.ok ? read.state : {};
      // The question's own values win over a start state (its numbers depend on them): say which.
      const own = Object.keys(question.state(questionParams(question, 'example')));
      const overridden = Object.keys(start).filter((k) => own.includes(k));
      note.textContent = overridden.length ? t('composer.overridden', { keys: overridden.join(', ') }) : '';
      return Object.keys(start).length ? { question: question.id, state: start } : { question: question.id };
    });
    const draft = {
      version: 1, title: title.value.trim(), reveal: reveal.value, ...(seed.value.trim() ? { seed: seed.value.trim() } : {}),
      lang: currentLanguage(), items,
    };
    const read = readSheet(draft);
    const all = items.length ? [...itemProblems, ...(read.ok ? [] : read.problems)] : [t('composer.pickOne')];
    current = !all.length && read.ok ? read.sheet : null;
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
    problems.replaceChildren(el('p', null, (await copyText(link.value)) ? t('composer.linkCopied') : t('composer.copyRefused')));
  });
  save.addEventListener('click', () => {
    if (current) downloadText('fresnel-lab-sheet.json', `${JSON.stringify(current, null, 2)}\n`, 'application/json');
  });
  scorm.addEventListener('click', async () => {
    if (!current) return;
    const sheet = current;
    scorm.disabled = true;
    problems.replaceChildren(el('p', null, t('composer.making')));
    try {
      const blob = await buildScormPackage(sheet);
      downloadBlob(`fresnel-lab-${fileSlug(sheet.title)}-scorm12.zip`, blob);
      problems.replaceChildren(el('p', null, t('composer.packageSaved', { size: grouped(blob.size / 1024) })));
    } catch (error) {
      problems.replaceChildren(el('p', 'hw-problem', error instanceof Error ? error.message : String(error)));
    } finally {
      scorm.disabled = !current;
    }
  });
  update();
  return { pick: (/** @type {string} */ id) => picks.find((p) => p.question.id === id)?.box, update };
}
