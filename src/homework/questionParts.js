// @ts-check
// What the question lists share: the indices and angles parameters are drawn from, and how their
// words print numbers: through src/ui/format.js, so a question reads 1,5 where the page's language
// writes a decimal comma (a parameter as it is drawn, 1.333; a computed value to fixed decimals).
import english from 'virtual:messages/en/questions';
import { messages } from '../i18n/messages.js';
import { MINUS, fixed as shownFixed, shownDecimal } from '../ui/format.js';
import { toDegrees } from '../optics/angles.js';
import { dielectricById, metalById } from '../optics/materials.js';

const t = messages('questions', english);

/** @typedef {ReturnType<typeof import('./seededRandom.js').seededRandom>} Random */
/** @typedef {Record<string, number | string | boolean>} PanelState  values a question's panel starts from */
/** @typedef {{ label: string, f: (thetaDeg: number) => number, level?: number }} Curve  what a prediction is drawn against */

// A question's functions are written as methods in these types: each question has parameters of
// its own shape P, and a list of them is then a list of Question (P unknown), whose functions take
// back what params() gave.
/**
 * @template P
 * @typedef {{ id: string, text(p: P): string, holds(p: P): boolean, why(p: P): string }} ChoiceOption
 */
/**
 * @template P
 * @typedef {{ id: string, panel: string, graded: string, params(rng: Random): P, prompt(p: P): string, state(p: P): PanelState }}
 *   QuestionCommon
 */
/**
 * @template P
 * @typedef {QuestionCommon<P> & { kind: 'numeric', unit: 'deg' | 'fraction' | null, tolerance: number, expected(p: P): number }}
 *   NumericQuestion
 */
/**
 * axis(), where given, names what the 0°–90° axis measures (else θ from the normal); axisInText() as a sentence names it.
 * @template P
 * @typedef {QuestionCommon<P> & { kind: 'predict', unit: 'deg', tolerance: number, expected(p: P): number, curve(p: P): Curve,
 *   axis?(): string, axisInText?(): string }} PredictQuestion
 */
/**
 * @template P
 * @typedef {QuestionCommon<P> & { kind: 'choice', options(p: P): ChoiceOption<P>[] }} ChoiceQuestion
 */
/**
 * @template [P=unknown]
 * @typedef {NumericQuestion<P> | PredictQuestion<P> | ChoiceQuestion<P>} Question
 */

/**
 * A question of the bank as it is written, its parameters' shape P taken from its params().
 * @template P
 * @param {Question<P>} spec
 * @returns {Question}
 */
export const question = (spec) => spec;

export const INDICES = Object.freeze([1.33, 1.45, 1.5, 1.6, 1.75, 2.0, 2.42]);
export const ANGLES = Object.freeze([30, 40, 45, 50, 55, 60, 65, 70, 75, 80]);

/** A computed value to `d` decimals, as shown. */
export const fixed = (/** @type {number} */ x, /** @type {number} */ d) => shownFixed(x, d);

/** A parameter as it was drawn (1.333, 45, 1.0000001), with the page's decimal separator. */
export const number = (/** @type {number} */ x) => String(x).replace('.', shownDecimal()).replace('-', MINUS);

/** Shown numbers one after another (a colour's channels, F at several indices). */
export const numberList = (/** @type {string[]} */ values) => values.join(t('listSeparator'));

/**
 * An angle in radians that a question's parameters always have (a critical angle from the denser
 * side, a transmitted angle from air), in degrees; null would be parameters drawn wrongly.
 * @param {number | null} radians
 */
export function degreesOf(radians) {
  if (radians === null) throw new RangeError('No such angle for these parameters.');
  return toDegrees(radians);
}

/**
 * The dielectric or metal of materials.json with this id: the questions name only materials it has.
 * @param {string} id
 */
export const dielectric = (id) => dielectricById(id) ?? unknownMaterial(id);
/** @param {string} id */
export const metal = (id) => metalById(id) ?? unknownMaterial(id);
/** @param {string} id @returns {never} */
const unknownMaterial = (id) => { throw new RangeError(`No material ${id} in materials.json.`); };
