// @ts-check
// The answers an LMS kept for the learner (cmi.suspend_data, written by connectScorm's save), read
// back as untrusted text: the LMS stores whatever it was given, and a learner, an administrator,
// an import or an older version of this page may have put something else there. Only answers
// that fit their question come back; whatever is refused is said in one sentence on the sheet.
import { readAnswer } from './gradeAnswer.js';
import { isObject, own } from '../host/own.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

// cmi.suspend_data is a CMIString4096 in SCORM 1.2 (RTE §3.4.2, cmi.suspend_data): this page never
// writes more, so anything longer is not its own and is not parsed.
export const SUSPEND_LIMIT = 4096;

const t = messages('homework', english);

/**
 * text: cmi.suspend_data as the LMS gave it; seed: the seed the sheet's numbers come from now;
 * classSeed: the sheet's own seed, or null; questions and params: the sheet's, in order.
 * Returns { answers, notice }: answers null (nothing usable) or one per question, each valid for
 * it (readAnswer) or null; notice null or a sentence for the learner.
 * @param {unknown} text
 * @param {{ seed: string, classSeed?: string | null, questions: readonly import('./questions.js').Question[],
 *   params: readonly unknown[] }} sheet
 * @returns {{ answers: (number | string | null)[] | null, notice: string | null }}
 */
export function readResume(text, { seed, classSeed = null, questions, params }) {
  // why: the notice's key (resume.<why>), each a whole sentence ending in what the sheet does instead.
  /** @type {(why: string | null, args?: Record<string, unknown>) => { answers: null, notice: string | null }} */
  const none = (why, args) => ({ answers: null, notice: why ? t(`resume.${why}`, args) : null });
  if (typeof text !== 'string' || text.trim() === '') return none(null); // the first visit
  if (text.length > SUSPEND_LIMIT) return none('tooLong', { length: text.length });
  /** @type {unknown} */
  let data;
  try {
    data = JSON.parse(text);
  } catch {
    return none('unreadable');
  }
  if (data === null) return none(null); // what an empty copy parsed to before
  const kept = own(data, 'answers');
  if (!Array.isArray(kept)) return none('otherForm');
  // The first version of this page kept { answers } alone, made for the sheet's class seed where it
  // had one (as now) and otherwise for the learner's id unhashed: other numbers than today's.
  const saysSeed = isObject(data) && Object.hasOwn(data, 'seed');
  const madeFor = saysSeed ? own(data, 'seed') : classSeed;
  if (madeFor !== seed) return none(saysSeed ? 'otherSeed' : 'earlierVersion');
  if (kept.length !== questions.length) return none('otherSheet', { kept: kept.length, count: questions.length });
  const answers = questions.map((question, i) => readAnswer(question, params[i], kept[i]));
  const dropped = answers.filter((a, i) => a === null && kept[i] !== null).length;
  const notice = dropped ? t('resume.dropped', { dropped }) : null;
  return { answers, notice };
}
