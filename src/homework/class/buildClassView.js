// @ts-check
// A class view from what the lecturer brings, in one call: the hand-ins read (readClassHandIns.js;
// a saved class view, classFile.js, adds its hand-ins and gives the sheet), graded in slices
// (gradeClass.js), the gradebook (buildGradebook.js) and what the class got wrong per question
// (summarizeQuestions.js). Every input ends as a graded hand-in or a refusal with its source.
// classWorker.js runs this in a worker; on the page's thread the grading yields between slices.
import { readClassHandIns } from './readClassHandIns.js';
import { classCaps } from './classCaps.js';
import { readClassFile } from './classFile.js';
import { gradeClass } from './gradeClass.js';
import { buildGradebook } from './buildGradebook.js';
import { summarizeQuestions } from './summarizeQuestions.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

const t = messages('class', english);

/**
 * @typedef {import('./readClassHandIns.js').HandIn} HandIn
 * @typedef {import('./readClassHandIns.js').Refusal} Refusal
 * @typedef {import('./readClassHandIns.js').PickedFile} PickedFile
 * @typedef {{ phase: 'reading' | 'grading' | 'summarising', done?: number, total?: number }} ViewProgress
 * @typedef {{ ok: true, sheet: import('../readSheet.js').Sheet, fingerprint: string, handIns: HandIn[],
 *   graded: import('./gradeClass.js').Graded[], refused: Refusal[], gradebook: import('./buildGradebook.js').Gradebook,
 *   summary: import('./summarizeQuestions.js').QuestionSummary[], problems?: undefined }
 *   | { ok: false, problems: string[] }} ClassView
 */

/**
 * request: { sheet (the sheet set, its JSON), files?, text?, classFile? (a saved view's text or
 * bytes: its sheet is used, and its hand-ins come first) }.
 * @param {{ sheet?: unknown, files?: PickedFile[] | unknown, text?: unknown, classFile?: unknown } | null | undefined} request
 *   (a worker passes on what it was sent: each part is checked where it is read)
 * @param {{ caps?: Partial<import('./classCaps.js').ClassCaps>, onProgress?: (progress: ViewProgress) => void, signal?: AbortSignal,
 *   pause?: () => Promise<unknown>, sliceMs?: number }} [options]
 * @returns {Promise<ClassView>}
 */
export async function buildClassView(request, { caps, onProgress, signal, pause, sliceMs } = {}) {
  let sheet = request?.sheet;
  /** @type {HandIn[]} */
  const handIns = [];
  /** @type {Refusal[]} */
  const refused = [];
  onProgress?.({ phase: 'reading' });
  if (request?.classFile !== undefined) {
    const saved = readClassFile(request.classFile, caps);
    if (saved.ok === false) return saved;
    sheet = saved.sheet;
    handIns.push(...saved.handIns);
    refused.push(...saved.refused);
  }
  if (sheet === undefined || sheet === null) return { ok: false, problems: [t('grade.giveSheet')] };
  // A saved view's hand-ins count against the cap on hand-ins read in all.
  const left = classCaps(caps).maxHandIns - handIns.length;
  const files = request?.files;
  const read = left > 0 ? readClassHandIns({ files, text: request?.text }, { ...caps, maxHandIns: left })
    : { handIns: [], refused: (Array.isArray(files) && files.length) || (typeof request?.text === 'string' && request.text.trim())
      ? [{ source: t('source.filesAndText'), reason: t('grade.savedViewFull') }] : [] };
  handIns.push(...read.handIns);
  refused.push(...read.refused);
  const grades = await gradeClass(sheet, handIns, {
    sliceMs, signal, pause, onProgress: (p) => onProgress?.({ phase: 'grading', ...p }),
  });
  if (grades.ok === false) return grades;
  onProgress?.({ phase: 'summarising' });
  const gradebook = buildGradebook(grades);
  return {
    ok: true, sheet: grades.sheet, fingerprint: grades.fingerprint, handIns, graded: grades.graded,
    refused: [...refused, ...grades.refused], gradebook, summary: summarizeQuestions(grades, gradebook),
  };
}
