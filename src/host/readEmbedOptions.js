// @ts-check
// The embed page's own URL parameters, beside the panel's: how it looks and who may drive it.
//   theme=light|dark, projector=1|0, reducedMotion=1|0   override what the browser remembers
//   audio=1|0                                             the audio trace of the R(θ) plots on or off (off by default)
//   lock=nI,nT  hide=nI,nT  controls=0                    controls shown but fixed, hidden, or none
//   fit=1                                                 laid out to show whole in its frame (a slide; fitToFrame.js)
//   lang=es                                               the language (else the reader's, else the browser's)
//   parentOrigin=https://deck.example                     the only origin messages go to and come from
// A value that cannot be used is named in `problems` and left out, but for parentOrigin: an
// author who asked for a restriction gets one, so an unusable origin leaves the panel deaf and
// mute to every page (`parentOrigin: 'none'`) rather than open to all.
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';

const t = messages('host', english);

/** These names belong to the embed page, so no panel's schema may use them. */
export const EMBED_KEYS = [
  'panel', 'theme', 'projector', 'reducedMotion', 'audio', 'lock', 'hide', 'controls', 'fit', 'lang', 'parentOrigin',
];

/** @param {string | null} raw */
const flag = (raw) => (raw === '1' || raw === 'true' ? true : raw === '0' || raw === 'false' ? false : undefined);
/** @param {string} raw */
const list = (raw) => raw.split(',').map((k) => k.trim()).filter(Boolean).slice(0, 64);

/**
 * The origin of an http(s) URL that names nothing but its origin (`https://Deck.example:443/`
 * gives `https://deck.example`), or null: a path, a query, a user name or another scheme is not
 * an origin.
 * @param {string} raw
 */
export function parseOrigin(raw) {
  try {
    const url = new URL(raw);
    const bare = url.pathname === '/' && !url.search && !url.hash && !url.username && !url.password
      && !raw.includes('?') && !raw.includes('#');
    return /^https?:$/.test(url.protocol) && bare ? url.origin : null;
  } catch {
    return null;
  }
}

/**
 * The embed page's options. theme, projector, reducedMotion: null where the link says nothing (the
 * reader's choice holds); parentOrigin: null (any page), 'none' (no page) or an origin.
 * @typedef {{ theme: 'light' | 'dark' | null, projector: boolean | null, reducedMotion: boolean | null, audio: boolean,
 *   lock: string[], hide: string[], controls: boolean, fit: boolean, parentOrigin: string | null }} EmbedOptions
 */

/**
 * @param {URLSearchParams} search
 * @returns {{ options: EmbedOptions, problems: import('./params.js').Problem[] }}
 */
export function readEmbedOptions(search) {
  /** @type {EmbedOptions} */
  const options = {
    theme: null, projector: null, reducedMotion: null, audio: false, lock: [], hide: [], controls: true, fit: false, parentOrigin: null,
  };
  /** @type {import('./params.js').Problem[]} */
  const problems = [];
  /** @param {string} key @param {string | null} raw @param {string} reason */
  const bad = (key, raw, reason) => problems.push({ key, raw, reason });
  if (search.has('theme')) {
    const raw = search.get('theme');
    if (raw === 'light' || raw === 'dark') options.theme = raw;
    else bad('theme', raw, t('reasonNotTheme'));
  }
  for (const key of /** @type {const} */ (['projector', 'reducedMotion', 'audio', 'controls', 'fit'])) {
    if (!search.has(key)) continue;
    const value = flag(search.get(key));
    if (value === undefined) bad(key, search.get(key), t('reasonNotFlag'));
    else options[key] = value;
  }
  for (const key of /** @type {const} */ (['lock', 'hide'])) if (search.has(key)) options[key] = list(search.get(key) ?? '');
  if (search.has('parentOrigin')) {
    options.parentOrigin = parseOrigin(search.get('parentOrigin') ?? '') ?? 'none';
    if (options.parentOrigin === 'none') {
      bad('parentOrigin', search.get('parentOrigin'), t('reasonNotOrigin'));
    }
  }
  return { options, problems };
}
