// @ts-check
// "Grade a class": the lecturer gives the sheet they set, then the class's hand-ins as they arrive
// (files, a folder, an LMS's zip, dropped or picked; codes pasted; a class view saved before). Every
// hand-in is graded again from the sheet, the seed and the answers (in a worker: runClassView.js);
// what cannot be used is listed with its name and reason. Out come a gradebook (a row per student,
// sortable; files for a spreadsheet and for the LMS's grade import: exportTools.js), what the class
// got wrong per question (a card each, one of which can be shown to the class with no name in it),
// and each student's report on demand. Those results' own code (the gradebook, the cards, the
// exports) is fetched when a class is first given: the section's first picture is its fields.
// Nothing leaves the browser.
import { button, el } from '../../../ui/el.js';
import { fixed, seconds } from '../../../ui/format.js';
import { field, titledSection } from '../../../ui/formParts.js';
import { readSetSheet } from '../readSetSheet.js';
import { gradedReport, problemBox } from '../gradedReport.js';
import { createClassRunner } from './runClassView.js';
import { fromDrop, fromInput, readPicked } from './pickedFiles.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../../i18n/messages.js';

const t = messages('class', english);

/** @typedef {[typeof import('./gradebookTable.js'), typeof import('./questionSummaries.js'), typeof import('./exportTools.js')]} Results */
/** @type {Promise<Results> | null} */
let resultModules = null;
/** The gradebook's, the cards' and the exports' modules, fetched once. */
const results = () => (resultModules ??= Promise.all([
  import('./gradebookTable.js'), import('./questionSummaries.js'), import('./exportTools.js')]));
/** What the status line says while a phase without counts runs (section.<phase>). */
const PHASES = ['reading', 'summarising'];

/** @param {{ accept?: string, multiple?: boolean, folder?: boolean }} [options] */
function fileInput({ accept = '', multiple = true, folder = false } = {}) {
  const input = el('input');
  input.type = 'file';
  input.multiple = multiple;
  if (accept) input.accept = accept;
  if (folder) input.setAttribute('webkitdirectory', '');
  return input;
}

/**
 * A modal dialog with a heading, a body and Close (and Print where asked); returns { open(body, title, from) }.
 * It opens at its top with the focus on its heading: what it shows comes first (on a projector at
 * 1280×720 a question shown to the class is taller than the screen, and focus on Close, at the end,
 * scrolled it out of view); Tab goes on to its buttons.
 * @param {string} className
 * @param {{ print?: boolean }} [options]
 */
function makeDialog(className, { print = false } = {}) {
  const dialog = el('dialog', className);
  const heading = el('h2');
  heading.id = `${className}-title`;
  heading.tabIndex = -1;
  dialog.setAttribute('aria-labelledby', heading.id);
  const tools = el('div', 'hw-dialog-tools');
  const close = button(t('dialog.close'));
  if (print) {
    const printButton = button(t('dialog.print'));
    printButton.addEventListener('click', () => window.print());
    tools.append(printButton);
  }
  tools.append(close);
  const body = el('div', 'hw-dialog-body');
  dialog.append(heading, body, tools);
  /** @type {HTMLElement | null} */
  let returnTo = null;
  close.addEventListener('click', () => dialog.close());
  dialog.addEventListener('close', () => { body.replaceChildren(); returnTo?.focus(); });
  return {
    dialog,
    /**
     * @param {Node} content
     * @param {string} title
     * @param {HTMLElement | null} [from]  where the focus goes back to on Close
     */
    open(content, title, from) {
      heading.textContent = title;
      body.replaceChildren(content);
      returnTo = from ?? null;
      dialog.showModal();
      heading.focus({ preventScroll: true });
      dialog.scrollTop = 0;
    },
  };
}

/** @typedef {Extract<import('../../class/buildClassView.js').ClassView, { ok: true }>} ClassView */

/**
 * The class section in `root`; returns its state (for the tests: runs, busy, the view and its table).
 * @param {Element} root
 */
export function buildClassSection(root) {
  const { section, heading } = titledSection('hw-class', 'class-title', t('section.title'));
  const sheet = el('input');
  sheet.type = 'text';
  sheet.placeholder = t('section.sheetPlaceholder');
  const files = fileInput({ accept: '.json,.txt,.html,.htm,.zip,application/json,application/zip,text/plain,text/html' });
  const folder = fileInput({ folder: true });
  const drop = el('div', 'hw-drop', t('section.drop'));
  const codes = el('textarea');
  codes.rows = 4;
  const saved = fileInput({ accept: '.json,application/json', multiple: false });
  const grade = button(t('section.grade'), 'hw-primary');
  const status = el('p', 'hw-class-status');
  status.setAttribute('role', 'status');
  const out = el('div', 'hw-class-out');
  const details = makeDialog('hw-student-dialog', { print: true });
  const showDialog = makeDialog('hw-show-dialog');
  section.append(heading, el('p', null, t('section.intro')), field(t('section.sheet'), sheet),
    field(t('section.files'), files), field(t('section.folder'), folder), drop, field(t('section.codes'), codes),
    field(t('section.saved'), saved), grade, status, out, details.dialog, showDialog.dialog);
  root.append(section);

  const runner = createClassRunner();
  /** @type {{ file: File, path: string }[]} */
  let dropped = [];
  /** @type {{ runs: number, busy: boolean, view: ClassView | null,
   *   table: ReturnType<typeof import('./gradebookTable.js').createGradebookTable> | null }} */
  const state = { runs: 0, busy: false, view: null, table: null };

  async function run() {
    results(); // fetched while the class is read and graded
    const file = saved.files?.[0];
    const classFile = file ? new Uint8Array(await file.arrayBuffer()) : undefined;
    const expected = readSetSheet(sheet.value);
    if (!expected.ok || (!expected.sheet && classFile === undefined)) {
      out.replaceChildren(problemBox(t('section.sheetUnusable'), expected.ok ? [t('section.giveSheet')] : expected.problems));
      status.textContent = '';
      return;
    }
    state.busy = true;
    grade.disabled = true;
    const started = performance.now();
    status.textContent = t('section.readingFiles');
    const picked = await readPicked([...fromInput(files.files), ...fromInput(folder.files), ...dropped]);
    const request = { sheet: expected.sheet ?? undefined, files: picked.files, text: codes.value, classFile };
    /** @type {import('../../class/buildClassView.js').ClassView | null} */
    let result;
    try {
      result = await runner.run(request, (p) => {
        status.textContent = p.phase === 'grading' && p.total
          ? t('section.grading', { done: p.done, total: p.total })
          : PHASES.includes(p.phase) ? t(`section.${p.phase}`) : status.textContent;
      });
    } catch (error) {
      result = { ok: false, problems: [t('section.stopped', { error: error instanceof Error ? error.message : String(error) })] };
    }
    state.busy = false;
    grade.disabled = false;
    if (result === null) return; // a newer run took over
    state.runs += 1;
    if (!result.ok) {
      out.replaceChildren(problemBox(t('section.cannotGrade'), result.problems));
      status.textContent = '';
      return;
    }
    const view = { ...result, refused: [...picked.refused, ...result.refused] };
    state.view = view;
    await showView(view, performance.now() - started);
  }

  /**
   * @param {ClassView} v
   * @param {number} ms  how long reading and grading took
   */
  async function showView(v, ms) {
    const [{ createGradebookTable, shownName }, { questionSummaries }, { buildExportTools }] = await results();
    const { gradebook } = v;
    const took = seconds(ms / 1000);
    const counts = {
      rows: gradebook.rows.length, students: gradebook.students, superseded: gradebook.superseded, refused: v.refused.length,
    };
    const shown = Object.fromEntries(Object.entries(counts).map(([key, n]) => [`${key}N`, fixed(n, 0)]));
    const graded = t('section.graded', { title: gradebook.title, ...counts, ...shown, where: runner.where(), took });
    status.textContent = runner.problem() ? `${graded} ${runner.problem()}` : graded;
    const parts = [];
    if (v.refused.length) {
      const box = el('details', 'hw-refused');
      box.open = v.refused.length <= 10;
      box.append(el('summary', null, t('section.refused', { count: v.refused.length, n: fixed(v.refused.length, 0) })));
      const list = el('ul');
      for (const r of v.refused) list.append(el('li', null, t('section.refusedItem', { source: r.source, reason: r.reason })));
      box.append(list);
      parts.push(box);
    }
    const exports = buildExportTools(v);
    const table = createGradebookTable(gradebook, {
      onDetails: (row, from) => {
        const graded = v.graded[row.key].result;
        const box = el('div');
        const flags = el('ul', 'hw-flag-list');
        for (const flag of row.flags) flags.append(el('li', null, flag.text));
        box.append(el('p', 'hw-meta', t('dialog.from', { source: row.source })));
        if (row.flags.length) box.append(flags);
        box.append(gradedReport(shownName(row), graded, { against: 'set' }));
        details.open(box, t('dialog.report', { name: shownName(row) }), from);
      },
    });
    state.table = table;
    const gradebookHeading = el('h3', null, t('section.gradebook'));
    const questionsHeading = el('h3', null, t('section.wrong'));
    const questionCards = () => questionSummaries(v, {
      onShow: (card, i, from) => {
        const copy = /** @type {HTMLElement} */ (card.cloneNode(true));
        copy.querySelector('.hw-show-class')?.remove();
        copy.querySelector('h4')?.removeAttribute('id');
        copy.removeAttribute('aria-labelledby');
        showDialog.open(copy, t('dialog.show', { title: gradebook.title, number: i + 1 }), from);
      },
    });
    parts.push(exports.files, gradebookHeading, table.element, exports.lms, questionsHeading);
    out.replaceChildren(...parts);
    await table.ready;
    // The cards after the rows, in tasks of their own.
    out.append(await questionCards());
  }

  grade.addEventListener('click', run);
  for (const input of [files, folder, saved]) {
    input.addEventListener('change', () => { if (sheet.value.trim() || saved.files?.length) run(); });
  }
  drop.addEventListener('dragover', (event) => { event.preventDefault(); drop.classList.add('hw-drop-over'); });
  drop.addEventListener('dragleave', () => drop.classList.remove('hw-drop-over'));
  drop.addEventListener('drop', async (event) => {
    event.preventDefault();
    drop.classList.remove('hw-drop-over');
    dropped = await fromDrop(event.dataTransfer);
    drop.textContent = t('section.dropped', { count: dropped.length, n: fixed(dropped.length, 0) });
    if (sheet.value.trim()) run();
  });
  return state;
}

