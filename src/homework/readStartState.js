// @ts-check
// A start state a lecturer gives a sheet item: "key=value&…", or a link copied from the panel
// (an embed link, or a lecture link whose keys carry the panel's prefix). Only the panel's values
// are kept: embed options (theme, lock, …) are the sheet page's business, not the item's. A name
// the panel does not have (a typo, or one every object inherits, such as constructor) is refused
// by name: the panel would drop it without a word. Each value is checked against the panel's
// schema here, so the lecturer hears of a bad one while composing rather than every student in the
// panel, and an alias is kept under the key it stands for, so the composer can tell that the
// question's own value wins over it.
import { EMBED_KEYS } from '../host/readEmbedOptions.js';
import { parseValue, rawText, resolveKey } from '../host/params.js';
import { lecturePrefix, panelEntry } from '../panels/manifest.js';
import { panelSchema } from '../panels/panelSchema.js';
import { panelTitle } from '../panels/panelText.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

const t = messages('homework', english);

const titleOf = (/** @type {string} */ panelId) => (panelEntry(panelId) ? panelTitle(panelId) : rawText(panelId));

/**
 * { ok: true, state } (possibly empty) or { ok: false, problem }.
 * @param {unknown} text
 * @param {string} panelId
 * (The other member's field is there, undefined, so that the loose project, which cannot narrow on `ok`, reads both.)
 * @returns {{ ok: true, state: import('./questionParts.js').PanelState, problem?: undefined }
 *   | { ok: false, problem: string, state?: undefined }}
 */
export function readStartState(text, panelId) {
  // Only text is read: String() of an object whose toString is not a function throws.
  const raw = typeof text === 'string' ? text.trim() : '';
  if (!raw) return { ok: true, state: {} };
  let search;
  try {
    // A whole link, a relative one (embed.html?…), or the pairs alone; a lecture link's #hash goes.
    search = /^[a-z]+:/i.test(raw) ? new URL(raw).searchParams : new URLSearchParams(raw.slice(raw.indexOf('?') + 1).replace(/#.*$/, ''));
  } catch {
    return { ok: false, problem: t('startState.notLink') };
  }
  const prefix = lecturePrefix(panelId);
  const fromLecture = !search.has('panel') && prefix && [...search.keys()].some((k) => k.startsWith(prefix));
  if (search.has('panel') && search.get('panel') !== panelId) {
    const other = search.get('panel') ?? '';
    return {
      ok: false,
      problem: panelEntry(other) ? t('startState.otherPanel', { other: panelTitle(other), panel: titleOf(panelId) })
        : t('startState.otherPage', { panel: titleOf(panelId) }),
    };
  }
  /** @type {import('../host/panelContract.js').Schema} */
  const schema = panelSchema(panelId) ?? {};
  /** @type {import('./questionParts.js').PanelState} */
  const state = {};
  /** @type {string[]} */
  const unknown = [];
  /** @type {string[]} */
  const refused = [];
  for (const [key, value] of search) {
    let name = null;
    if (fromLecture) name = key.startsWith(prefix) ? key.slice(prefix.length) : null;
    else if (!EMBED_KEYS.includes(key) && !key.includes('.')) name = key;
    if (name === null) continue;
    const own = resolveKey(schema, name);
    if (own === undefined) {
      unknown.push(rawText(name));
      continue;
    }
    const read = parseValue(schema[own], value);
    // A text keeps the form its link has (a shader's code stays compact): the panel decodes it.
    if (read.ok) state[own] = schema[own].type === 'text' ? value : read.value;
    else refused.push(`${rawText(name)}=${rawText(value)} ${read.reason}`);
  }
  const problems = [];
  if (unknown.length) problems.push(t('startState.unknown', { count: unknown.length, names: unknown.join(', '), panel: titleOf(panelId) }));
  if (refused.length) problems.push(`${refused.join('; ')}.`);
  return problems.length ? { ok: false, problem: problems.join(' ') } : { ok: true, state };
}
