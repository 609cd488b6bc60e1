// A start state a lecturer gives a sheet item: "key=value&…", or a link copied from the panel
// (an embed link, or a lecture link whose keys carry the panel's prefix). Only the panel's values
// are kept: embed options (theme, lock, …) are the sheet page's business, not the item's.
import { EMBED_KEYS } from '../host/readEmbedOptions.js';
import { lecturePrefix, panelEntry } from '../panels/manifest.js';

const typed = (raw) => (raw === 'true' ? true : raw === 'false' ? false : raw.trim() !== '' && Number.isFinite(Number(raw)) ? Number(raw) : raw);

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
  const state = {};
  for (const [key, value] of search) {
    if (fromLecture) {
      if (key.startsWith(prefix)) state[key.slice(prefix.length)] = typed(value);
    } else if (!EMBED_KEYS.includes(key) && !key.includes('.')) {
      state[key] = typed(value);
    }
  }
  return { ok: true, state };
}
