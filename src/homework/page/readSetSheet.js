// @ts-check
// The sheet a lecturer set, as they give it to check hand-ins against: its link (?sheet=CODE), the
// bare code, or the sheet file's JSON. Empty text is no sheet (ok, null).
import { readSheet } from '../readSheet.js';
import { sheetFromCode } from '../sheetCodes.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);

/**
 * The sheet to check against, from a link, a code or a sheet's JSON: { ok, sheet } or problems.
 * @param {string} text
 * @returns {{ ok: true, sheet: import('../readSheet.js').Sheet | null, problems?: undefined }
 *   | { ok: false, problems: string[], sheet?: undefined }}
 */
export function readSetSheet(text) {
  const raw = text.trim();
  if (!raw) return { ok: true, sheet: null };
  /** @type {unknown} */
  let data;
  if (raw.startsWith('{')) {
    try {
      data = JSON.parse(raw);
    } catch {
      return { ok: false, problems: [t('setSheet.notJson')] };
    }
  } else {
    let code = raw;
    try {
      code = new URL(raw, window.location.href).searchParams.get('sheet') ?? raw;
    } catch { /* not a link: a bare code */ }
    const decoded = sheetFromCode(code);
    if (!decoded.ok) return { ok: false, problems: decoded.problems };
    data = decoded.data;
  }
  const read = readSheet(data);
  return read.ok ? read : { ok: false, problems: read.problems.map((problem) => t('setSheet.problem', { problem })) };
}
