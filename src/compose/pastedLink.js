// @ts-check
// A start state for a panel item from a link the lecturer copied: the panel's "Copy link" on the
// lecture page (index.html?spheres.nT=…#spheres: the hero's keys unprefixed, every other panel's
// as <id>.<key>), its "Copy embed code" or embed link (embed.html?panel=<id>&nT=…&lock=…), a
// composed lecture's link (index.html?lecture=L1.…: the first item of this panel), or the pairs
// alone (nT=1.5&kd=ff0000). The text comes from anyone's clipboard: it is read with the host's own
// readers (params.js, readEmbedOptions.js, lectureLink.js), every value must pass the panel's
// schema, and every key refused is named. Never throws.
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { applyParams, defaults, describeProblem, rawText } from '../host/params.js';
import { fixed } from '../ui/format.js';
import { EMBED_KEYS, readEmbedOptions } from '../host/readEmbedOptions.js';
import { lecturePrefix, panelEntry } from '../panels/manifest.js';
import { panelSchema } from '../panels/panelSchema.js';
import { lectureFromCode } from '../lecture/lectureLink.js';
import { itemKeys } from '../lecture/openLecture.js';
import { panelTitle } from '../panels/panelText.js';

const t = messages('compose', english);
export const MAX_PASTED = 120_000; // characters: a shader lab link with its code is a few kilobytes
const MAX_PAIRS = 200;

/**
 * What a pasted link gives a panel item, or why it gives it nothing. (The other member's fields
 * are there, undefined, so that the loose project, which cannot narrow on `ok`, reads both.)
 * @typedef {{ ok: true, state: Record<string, import('../host/panelContract.js').Value>, lock: string[], hide: string[],
 *   problems: string[], source: 'embed' | 'lecture' | 'composed' | 'pairs' }
 *   | { ok: false, problems: string[], state?: undefined, lock?: undefined, hide?: undefined, source?: undefined }} PastedLink
 */

const titleOf = (/** @type {string} */ id) => (panelEntry(id) ? panelTitle(id) : rawText(id));

/**
 * The query of a pasted text: a whole link, a relative one, an <iframe> snippet, or bare pairs.
 * @param {string} text
 * @returns {URLSearchParams | null}
 */
function searchOf(text) {
  let raw = text;
  const src = /<iframe\b[^>]*?\ssrc\s*=\s*"([^"]*)"/i.exec(raw);
  // The embed snippet escapes & as &amp; in its src attribute.
  if (src) raw = src[1].replace(/&quot;/g, '"').replace(/&lt;/g, '<').replace(/&amp;/g, '&');
  try {
    if (/^[a-z][a-z0-9+.-]*:/i.test(raw)) return new URL(raw).searchParams;
    const query = raw.includes('?') ? raw.slice(raw.indexOf('?') + 1) : raw;
    return new URLSearchParams(query.replace(/#.*$/s, ''));
  } catch {
    return null;
  }
}

/**
 * { ok: true, state, lock, hide, problems, source } — the values, locked and hidden controls the
 * link gives this panel (values checked by its schema; keys and values refused are named in
 * problems) — or { ok: false, problems } when the text is no link of this panel at all.
 * source says what kind of link it was: 'embed', 'lecture', 'composed' or 'pairs'.
 * @param {unknown} text
 * @param {string} panelId
 * @returns {PastedLink}
 */
export function readPastedLink(text, panelId) {
  const schema = panelSchema(panelId);
  if (!schema || !panelEntry(panelId)) return { ok: false, problems: [t('pasteNoPanel', { id: rawText(panelId) })] };
  if (typeof text !== 'string' || !text.trim()) return { ok: false, problems: [t('pasteEmpty')] };
  if (text.length > MAX_PASTED) {
    return { ok: false, problems: [t('pasteTooLong', { length: fixed(text.length, 0), max: fixed(MAX_PASTED, 0) })] };
  }
  const search = searchOf(text.trim());
  if (!search) return { ok: false, problems: [t('pasteNotLink')] };
  /** @type {[string, string][]} */
  const all = [];
  search.forEach((value, key) => { all.push([key, value]); });
  const pairs = all.slice(0, MAX_PAIRS);
  /** @type {string[]} */
  const problems = [];
  if (all.length > MAX_PAIRS) problems.push(t('pasteTooMany', { max: fixed(MAX_PAIRS, 0) }));

  const hash = /#([A-Za-z0-9-]+)\s*$/.exec(text.trim())?.[1];
  if (search.has('lecture')) return fromComposed(search.get('lecture') ?? '', panelId, hash, pairs, problems);

  const embedPanel = search.get('panel');
  if (embedPanel !== null && embedPanel !== panelId) {
    return { ok: false, problems: [t('pasteOtherPanel', { other: titleOf(embedPanel), title: titleOf(panelId) })] };
  }
  const prefix = lecturePrefix(panelId);
  // A link without panel= is the lecture page's (its #hash names the panel it was copied from).
  const isLink = /^[a-z][a-z0-9+.-]*:|\?|<iframe/i.test(text.trim());
  /** @type {'embed' | 'lecture' | 'pairs'} */
  const source = embedPanel !== null ? 'embed' : isLink ? 'lecture' : 'pairs';
  if (source === 'lecture' && hash && hash !== panelId && panelEntry(hash)) {
    return { ok: false, problems: [t('pasteOtherPanel', { other: titleOf(hash), title: titleOf(panelId) })] };
  }
  // A lecture link holds every panel's values: this panel's are its prefixed keys (the hero's, the
  // keys without a dot), the rest belong to other panels and are passed over without a word.
  const own = pairs.filter(([key]) => (source === 'lecture' ? (prefix ? key.startsWith(prefix) : !key.includes('.'))
    : !EMBED_KEYS.includes(key)));
  if (source === 'lecture' && !own.length && hash !== panelId) {
    return { ok: false, problems: [t('pasteNoValues', { title: titleOf(panelId) })] };
  }
  const update = Object.fromEntries(own.map(([key, value]) => [source === 'lecture' ? key.slice(prefix.length) : key, value]));
  const { applied, rejected } = applyParams(schema, defaults(schema), update);
  for (const r of rejected) problems.push(describeProblem({ ...r, fallback: undefined }));

  /** @type {string[]} */
  let lock = [];
  /** @type {string[]} */
  let hide = [];
  if (source === 'embed') {
    const { options, problems: optionProblems } = readEmbedOptions(search);
    for (const p of optionProblems) if (p.key !== 'parentOrigin') problems.push(describeProblem({ ...p, fallback: undefined }));
    /** @type {(names: string[], what: string) => string[]} */
    const keys = (names, what) => names.filter((name) => {
      if (Object.hasOwn(schema, name)) return true;
      problems.push(t('pasteNoControl', { option: what, name: rawText(name) }));
      return false;
    });
    lock = keys(options.lock, 'lock');
    hide = keys(options.hide, 'hide');
  }
  return { ok: true, state: applied, lock, hide, problems, source };
}

/**
 * A panel of a composed lecture's link: the item its #hash names (else the lecture's first of this
 * panel), started where the lecture starts it, with the values the link carries under that item's
 * prefix (the lecture page's keys, openLecture.js's itemKeys) on top.
 * @param {string} code
 * @param {string} panelId
 * @param {string | undefined} hash
 * @param {[string, string][]} pairs
 * @param {string[]} problems
 * @returns {PastedLink}
 */
function fromComposed(code, panelId, hash, pairs, problems) {
  const read = lectureFromCode(code);
  if (!read.ok || !read.lecture) return { ok: false, problems: read.problems };
  const items = read.lecture.items;
  const keys = itemKeys(items, lecturePrefix);
  const named = hash ? keys.findIndex((k) => k.key === hash) : -1;
  const chosen = named >= 0 ? items[named] : undefined;
  if (chosen && (chosen.type !== 'panel' || chosen.panel !== panelId)) {
    const other = chosen.type === 'panel' ? titleOf(chosen.panel) : '';
    return { ok: false, problems: [t('pasteOtherItem', { type: chosen.type, other, title: titleOf(panelId) })] };
  }
  const at = named >= 0 ? named : items.findIndex((i) => i.type === 'panel' && i.panel === panelId);
  const item = at >= 0 ? items[at] : undefined;
  if (!item || item.type !== 'panel') return { ok: false, problems: [t('pasteNoSuchPanel', { title: titleOf(panelId) })] };
  const schema = panelSchema(panelId) ?? {};
  const { prefix } = keys[at];
  const own = pairs.filter(([key]) => key !== 'lecture' && (prefix ? key.startsWith(prefix) : !key.includes('.')));
  const update = Object.fromEntries(own.map(([key, value]) => [key.slice((prefix ?? '').length), value]));
  const { applied, rejected } = applyParams(schema, { ...defaults(schema), ...item.state }, update);
  for (const r of rejected) problems.push(describeProblem({ ...r, fallback: undefined }));
  return {
    ok: true, state: { ...item.state, ...applied }, lock: [...(item.lock ?? [])], hide: [...(item.hide ?? [])],
    problems: [...read.problems, ...problems], source: 'composed',
  };
}
