// What the question lists share: the indices and angles parameters are drawn from, and how their
// words print numbers: through src/ui/format.js, so a question reads 1,5 where the page's language
// writes a decimal comma (a parameter as it is drawn, 1.333; a computed value to fixed decimals).
import english from 'virtual:messages/en/questions';
import { messages } from '../i18n/messages.js';
import { MINUS, fixed as shownFixed, shownDecimal } from '../ui/format.js';

const t = messages('questions', english);

export const INDICES = Object.freeze([1.33, 1.45, 1.5, 1.6, 1.75, 2.0, 2.42]);
export const ANGLES = Object.freeze([30, 40, 45, 50, 55, 60, 65, 70, 75, 80]);

/** A computed value to `d` decimals, as shown. */
export const fixed = (x, d) => shownFixed(x, d);

/** A parameter as it was drawn (1.333, 45, 1.0000001), with the page's decimal separator. */
export const number = (x) => String(x).replace('.', shownDecimal()).replace('-', MINUS);

/** Shown numbers one after another (a colour's channels, F at several indices). */
export const numberList = (values) => values.join(t('listSeparator'));
