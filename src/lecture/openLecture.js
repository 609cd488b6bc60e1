// @ts-check
// Which lecture the lecture page shows: the one in the link (?lecture=CODE), else one written into
// the page itself (a data element, as the offline export writes it), else the lab's own lecture.
// Both are text from anyone: read by lectureFromCode / readLecture, which name what they refuse.
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';
import { lectureFromCode } from './lectureLink.js';
import { fixed } from '../ui/format.js';
import { readLecture } from './readLecture.js';

export { LECTURE_ELEMENT_ID } from './lectureElement.js';
const t = messages('lecture', english);
const MAX_ELEMENT = 400_000; // characters, as much as a code may unpack to (lectureLink.js)

/**
 * @typedef {object} OpenedLecture
 * @property {'default' | 'link' | 'data'} source where the lecture came from ('default': none was given, or none could be read)
 * @property {import('./readLecture.js').Lecture | null} lecture the lecture as readLecture gives it, or null for the lab's own
 * @property {string[]} problems what was refused, in words (parts of a lecture that opens, or the whole)
 * @property {boolean} refused a lecture was given but could not be read at all
 * @property {'link' | 'data' | null} given where a lecture was given (also when it was refused)
 */

/**
 * search: the page's query (URLSearchParams); elementText: the data element's text, or null where
 * there is none. Never throws.
 * @param {URLSearchParams} search
 * @param {string | null} elementText
 * @returns {OpenedLecture}
 */
export function openLecture(search, elementText) {
  /** @type {'link' | 'data'} */
  let source;
  /** @type {import('./readLecture.js').ReadLecture} */
  let read;
  if (search.has('lecture')) {
    source = 'link';
    read = lectureFromCode(search.get('lecture'));
  } else if (elementText !== null) {
    source = 'data';
    read = readElement(elementText);
  } else {
    return { source: 'default', lecture: null, problems: [], refused: false, given: null };
  }
  if (!read.ok) return { source: 'default', lecture: null, problems: read.problems, refused: true, given: source };
  // A lecture whose every item was refused would be an empty page: it is refused whole, its reasons named.
  if (!read.lecture.items.length) {
    const problems = [...read.problems, t('nothingToShow')];
    return { source: 'default', lecture: null, problems, refused: true, given: source };
  }
  return { source, lecture: read.lecture, problems: read.problems, refused: false, given: source };
}

/**
 * The data element's JSON, read as readLecture reads any lecture.
 * @param {string} text
 * @returns {import('./readLecture.js').ReadLecture}
 */
function readElement(text) {
  if (text.length > MAX_ELEMENT) {
    return { ok: false, problems: [t('elementTooLong', { length: fixed(text.length, 0), max: fixed(MAX_ELEMENT, 0) })] };
  }
  /** @type {unknown} */
  let data;
  try {
    data = JSON.parse(text);
  } catch {
    return { ok: false, problems: [t('elementNotJson')] };
  }
  return readLecture(data);
}

/**
 * The key of each item of a composed lecture: its section's id, its host's name and (for a panel)
 * the prefix of its values in the page's link. A panel's first item keeps the keys it has on the
 * lab's own lecture (its id; the hero's values unprefixed, the others' as `id.key`), so a link made
 * there opens the same view here; a later item of the same panel is `id--2`, `id--3`… (its values
 * `id--2.key`), and a text or question item is `text--N` or `question--N` (N its place in the lecture).
 * A panel id never holds `--` (manifest.js), so no key is another's.
 * @param {readonly import('./readLecture.js').LectureItem[]} items
 * @param {(id: string) => string} lecturePrefix the prefix a panel's values have on the lab's own lecture
 * @returns {{ key: string, prefix: string | null }[]}
 */
export function itemKeys(items, lecturePrefix) {
  /** @type {Map<string, number>} */
  const seen = new Map();
  return items.map((item, i) => {
    if (item.type !== 'panel') return { key: `${item.type}--${i + 1}`, prefix: null };
    const count = (seen.get(item.panel) ?? 0) + 1;
    seen.set(item.panel, count);
    if (count === 1) return { key: item.panel, prefix: lecturePrefix(item.panel) };
    return { key: `${item.panel}--${count}`, prefix: `${item.panel}--${count}.` };
  });
}
