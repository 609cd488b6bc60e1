// An index of refraction as the reader set it (1.5, 1.3333, 1.000293): the digits it has and no more,
// with the page's decimal separator. format.js's fixed with as many decimals as String(n) writes gives
// the same digits as String(n), since both take the decimal nearest to the number.
import { fixed } from '../../ui/format.js';

export function indexText(n) {
  const text = String(n);
  if (!/^-?\d+(\.\d+)?$/.test(text)) return text; // an exponent, NaN or Infinity: as JavaScript writes it
  return fixed(n, text.split('.')[1]?.length ?? 0);
}
