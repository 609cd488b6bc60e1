// @ts-check
// Parameters of the `shader-lab` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { EXERCISE_IDS, MAX_CODE } from './exerciseIds.js';
import { decodeCode, encodeCode } from './codeCodec.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  exercise: { type: 'enum', default: 'schlick', options: [...EXERCISE_IDS] },
  // Empty: the exercise's starting code. The editor shows the code; the link keeps it compact.
  // Twice the panel's own limit: longer code reaches the panel, which refuses it in its own words.
  code: {
    type: 'text', default: '', maxLength: 2 * MAX_CODE, encode: encodeCode, decode: decodeCode,
    defaultText: 'starterCode', // host.defaultText.starterCode: the exercise’s starting code
  },
  precision: { type: 'enum', default: 'highp', options: ['highp', 'mediump'] },
  homework: { type: 'boolean', default: false },
};
