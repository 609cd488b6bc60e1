// A start state a lecturer gives a sheet item: "key=value&…", or a link copied from the panel
// (an embed link, or a lecture link whose keys carry the panel's prefix). Only the panel's values
// are kept: embed options (theme, lock, …) are the sheet page's business, not the item's. A name
// the panel does not have (a typo, or one every object inherits, such as constructor) is refused
// by name: the panel would drop it without a word.
import { EMBED_KEYS } from '../host/readEmbedOptions.js';
import { rawText, readNumber, resolveKey } from '../host/params.js';
import { lecturePrefix, panelEntry } from '../panels/manifest.js';
import { panelSchema } from '../panels/panelSchema.js';

const typed = (raw) => (raw === 'true' ? true : raw === 'false' ? false : Number.isFinite(readNumber(raw)) ? readNumber(raw) : raw);

/** { ok: true, state } (possibly empty) or { ok: false, problem }. */
export function readStartState(text, panelId) {
  const raw = String(text ?? '').trim();
  if (!raw) return { ok: true, state: {} };
  let search;
  try {
    // A whole link, a relative one (embed.html?…), or the pairs alone; a lecture link's #hash goes.
    search = /^[a-z]+:/i.test(raw) ? new URL(raw).searchParams : new URLSearchParams(raw.slice(raw.indexOf('?') + 1).replace(/#.*$/, ''));
  } catch {
    return { ok: false, problem: 'This is neither a link nor key=value pairs.' };
  }
  const prefix = lecturePrefix(panelId);
  const fromLecture = !search.has('panel') && prefix && [...search.keys()].some((k) => k.startsWith(prefix));
  if (search.has('panel') && search.get('panel') !== panelId) {
    const other = panelEntry(search.get('panel'))?.title ?? 'another page';
    return { ok: false, problem: `This link is for “${other}”, not “${panelEntry(panelId).title}”.` };
  }
  const schema = panelSchema(panelId) ?? {};
  const state = {};
  const unknown = [];
  for (const [key, value] of search) {
    let name = null;
    if (fromLecture) name = key.startsWith(prefix) ? key.slice(prefix.length) : null;
    else if (!EMBED_KEYS.includes(key) && !key.includes('.')) name = key;
    if (name === null) continue;
    if (resolveKey(schema, name) === undefined) unknown.push(rawText(name));
    else state[name] = typed(value);
  }
  if (unknown.length) {
    return { ok: false, problem: `${unknown.join(', ')} ${unknown.length === 1 ? 'is not a value' : 'are not values'} of the “${panelEntry(panelId).title}” panel.` };
  }
  return { ok: true, state };
}
