// The embed page's own URL parameters, beside the panel's: how it looks and who may drive it.
//   theme=light|dark, projector=1|0, reducedMotion=1|0   override what the browser remembers
//   lock=nI,nT  hide=nI,nT  controls=0                    controls shown but fixed, hidden, or none
//   parentOrigin=https://deck.example                     the only origin messages go to and come from
// A value that cannot be used is named in `problems` and left out.

/** These names belong to the embed page, so no panel's schema may use them. */
export const EMBED_KEYS = ['panel', 'theme', 'projector', 'reducedMotion', 'lock', 'hide', 'controls', 'parentOrigin'];

const flag = (raw) => (raw === '1' || raw === 'true' ? true : raw === '0' || raw === 'false' ? false : undefined);
const list = (raw) => raw.split(',').map((k) => k.trim()).filter(Boolean).slice(0, 64);

/** An http(s) origin as written (`https://host[:port]`), or null. */
export function parseOrigin(raw) {
  try {
    const url = new URL(raw);
    const origin = raw.replace(/\/$/, '');
    return /^https?:$/.test(url.protocol) && url.origin === origin ? origin : null;
  } catch {
    return null;
  }
}

/** @param {URLSearchParams} search */
export function readEmbedOptions(search) {
  const options = { theme: null, projector: null, reducedMotion: null, lock: [], hide: [], controls: true, parentOrigin: null };
  const problems = [];
  const bad = (key, raw, reason) => problems.push({ key, raw, reason });
  if (search.has('theme')) {
    const raw = search.get('theme');
    if (raw === 'light' || raw === 'dark') options.theme = raw;
    else bad('theme', raw, 'is not light or dark');
  }
  for (const key of ['projector', 'reducedMotion', 'controls']) {
    if (!search.has(key)) continue;
    const value = flag(search.get(key));
    if (value === undefined) bad(key, search.get(key), 'is not 1 or 0');
    else options[key] = value;
  }
  for (const key of ['lock', 'hide']) if (search.has(key)) options[key] = list(search.get(key));
  if (search.has('parentOrigin')) {
    options.parentOrigin = parseOrigin(search.get('parentOrigin'));
    if (!options.parentOrigin) bad('parentOrigin', search.get('parentOrigin'), 'is not an origin like https://deck.example');
  }
  return { options, problems };
}
