// The names of a stability map's classes, in the page's language: what the map figures, the
// exported picture and the panels' sentences call them. Words only (no DOM), so a panel's words.js
// can name a class without importing a figure and its styles.
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

const t = messages('panelsShared', english);
const CLASS_WORDS = Object.freeze({
  fine: 'classFine', aboveTolerance: 'classAboveTolerance', outOfRange: 'classOutOfRange', notFinite: 'classNotFinite',
});

/** A class's name in the page's language: fine, error above tolerance, outside [0, 1], NaN or infinite. */
export const classLabel = (cls) => t(CLASS_WORDS[cls]);

/** The same by class, read when the words are written (each a getter). */
export const CLASS_LABELS = Object.freeze(Object.defineProperties({}, Object.fromEntries(
  Object.keys(CLASS_WORDS).map((cls) => [cls, { get: () => classLabel(cls), enumerable: true }]),
)));
