// The emulation gap (src/methods/emulationGap.js) as a message's arguments: the device, the date in
// the page's language, and the ranges with the page's decimal separator.
import { EMULATION_GAP } from '../../methods/emulationGap.js';
import { fixed } from '../../ui/format.js';
import { pageLocale } from '../../ui/safeLocale.js';

export function emulationGapWords() {
  const { device, date, highp, mediump } = EMULATION_GAP;
  return {
    device,
    date: new Date(`${date}T12:00:00Z`).toLocaleDateString(pageLocale(), { dateStyle: 'medium', timeZone: 'UTC' }),
    highLow: fixed(highp[0], 1), highHigh: fixed(highp[1], 1), mediumLow: fixed(mediump[0], 1), mediumHigh: fixed(mediump[1], 1),
  };
}
