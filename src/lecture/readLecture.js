// A lecture as data: a title and a list of items, each a panel (its id, where it starts, controls
// locked or hidden as an embed link has them, a heading and text of the lecturer's own), a text
// item (an agenda, a reference list), or a question from the homework bank asked of the room.
// A lecture comes from anyone (a link, a file), so it is read as untrusted data: own keys only,
// sizes capped, every value checked against the panel's schema, and whatever cannot be used is
// named while the rest of the lecture is kept.
import { applyParams, defaults, describeProblem, rawText, resolveKey } from '../host/params.js';
import { panelEntry } from '../panels/manifest.js';
import { panelSchema } from '../panels/panelSchema.js';
import { questionById } from '../homework/questions.js';

export const LECTURE_KIND = 'fresnel-lab-lecture';
export const LECTURE_VERSION = 1;
/** The seed of a question item that names none: the same numbers on the page, in the deck and in the composer. */
export const ROOM_SEED = 'lecture';

export const LECTURE_CAPS = Object.freeze({ items: 80, title: 200, heading: 200, text: 4000, keys: 64, seed: 64 });
const ITEM_FIELDS = {
  panel: ['type', 'panel', 'state', 'lock', 'hide', 'heading', 'text'],
  text: ['type', 'heading', 'text'],
  question: ['type', 'question', 'seed', 'heading', 'text'],
};

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const own = (o, key) => (Object.hasOwn(o, key) ? o[key] : undefined);

/** An optional text: undefined when absent, else the text or a problem (not text, too long). */
function optionalText(value, max, what, problems) {
  if (value === undefined) return undefined;
  if (typeof value !== 'string') { problems.push(`${what} is not text, so it is left out.`); return undefined; }
  if (value.length > max) {
    problems.push(`${what} has ${value.length} characters, more than ${max}, so it is left out.`);
    return undefined;
  }
  return value;
}

/** A list of the panel's control keys (locked or hidden), each resolved to its schema key. */
function keyList(value, schema, what, problems) {
  if (value === undefined) return undefined;
  if (!Array.isArray(value) || value.length > LECTURE_CAPS.keys) {
    problems.push(`${what} is not a list of up to ${LECTURE_CAPS.keys} control names, so it is left out.`);
    return undefined;
  }
  const keys = [];
  for (const name of value) {
    const key = typeof name === 'string' ? resolveKey(schema, name) : undefined;
    if (key === undefined) problems.push(`${what}: ${rawText(name, 40)} is no control of this panel.`);
    else if (!keys.includes(key)) keys.push(key);
  }
  return keys;
}

function readPanelItem(item, where, problems) {
  const id = own(item, 'panel');
  const schema = typeof id === 'string' ? panelSchema(id) : undefined;
  if (!schema || !panelEntry(id)) {
    return problems.push(`${where}: ${rawText(id, 40)} is no panel of the lab, so the item is left out.`) && null;
  }
  const out = { type: 'panel', panel: id };
  const state = own(item, 'state');
  if (state !== undefined) {
    if (!isObject(state)) problems.push(`${where}: its start state is not a set of values, so the panel starts from its defaults.`);
    else {
      // Read as a link is: each value checked by the schema, what is refused named; defaults are not stored.
      const start = defaults(schema);
      const { applied, rejected } = applyParams(schema, { ...start }, Object.fromEntries(Object.keys(state).map((k) => [k, state[k]])));
      for (const r of rejected) problems.push(`${where}: ${describeProblem(r)}`);
      const kept = Object.fromEntries(Object.entries(applied).filter(([k, v]) => !Object.is(v, start[k])));
      if (Object.keys(kept).length) out.state = kept;
    }
  }
  for (const field of ['lock', 'hide']) {
    const keys = keyList(own(item, field), schema, `${where}, ${field}`, problems);
    if (keys?.length) out[field] = keys;
  }
  return out;
}

function readQuestionItem(item, where, problems) {
  const id = own(item, 'question');
  if (typeof id !== 'string' || !questionById(id)) {
    return problems.push(`${where}: ${rawText(id, 40)} is no question of the homework bank, so the item is left out.`) && null;
  }
  const out = { type: 'question', question: id };
  const seed = optionalText(own(item, 'seed'), LECTURE_CAPS.seed, `${where}, its seed`, problems);
  if (seed !== undefined && seed.trim()) out.seed = seed.trim();
  return out;
}

/** One item, or null (named in problems) when it cannot be used. */
function readItem(item, i, problems) {
  const where = `Item ${i + 1}`;
  if (!isObject(item)) return problems.push(`${where} is not an item, so it is left out.`) && null;
  const type = own(item, 'type');
  const fields = typeof type === 'string' && Object.hasOwn(ITEM_FIELDS, type) ? ITEM_FIELDS[type] : null;
  if (!fields) {
    return problems.push(`${where}: ${rawText(type, 40)} is no kind of item (panel, text or question), so it is left out.`) && null;
  }
  for (const key of Object.keys(item)) {
    if (!fields.includes(key)) problems.push(`${where}: ${rawText(key, 40)} is no field of a ${type} item, so it is left out.`);
  }
  const out = type === 'panel' ? readPanelItem(item, where, problems)
    : type === 'question' ? readQuestionItem(item, where, problems)
    : { type: 'text' };
  if (!out) return null;
  const heading = optionalText(own(item, 'heading'), LECTURE_CAPS.heading, `${where}, its heading`, problems);
  const text = optionalText(own(item, 'text'), LECTURE_CAPS.text, `${where}, its text`, problems);
  if (heading?.trim()) out.heading = heading.trim();
  if (text?.trim()) out.text = text.trim();
  if (type === 'text' && !out.text && !out.heading) {
    return problems.push(`${where} is a text item without text, so it is left out.`) && null;
  }
  return out;
}

/**
 * { ok: true, lecture: { kind, version, title, items }, problems } — the lecture as far as it can
 * be used, each part left out named in problems — or { ok: false, problems } when the data is no
 * lecture at all. Never throws.
 */
export function readLecture(data) {
  if (!isObject(data)) return { ok: false, problems: ['A lecture is a JSON object with a title and a list of items.'] };
  if (own(data, 'kind') !== LECTURE_KIND) {
    return { ok: false, problems: [`This is not a lecture (its kind is ${rawText(own(data, 'kind'), 40)}, not ${LECTURE_KIND}).`] };
  }
  if (own(data, 'version') !== LECTURE_VERSION) {
    return {
      ok: false,
      problems: [`This lecture is version ${rawText(own(data, 'version'), 20)}; this page reads version ${LECTURE_VERSION}.`],
    };
  }
  const problems = [];
  for (const key of Object.keys(data)) {
    if (!['kind', 'version', 'title', 'items'].includes(key)) {
      problems.push(`${rawText(key, 40)} is no field of a lecture, so it is left out.`);
    }
  }
  const title = optionalText(own(data, 'title'), LECTURE_CAPS.title, 'The title', problems)?.trim() || 'A lecture';
  const raw = own(data, 'items');
  if (!Array.isArray(raw)) return { ok: false, problems: ['A lecture holds a list of items.'] };
  if (raw.length > LECTURE_CAPS.items) problems.push(`The lecture has ${raw.length} items; the first ${LECTURE_CAPS.items} are read.`);
  const items = raw.slice(0, LECTURE_CAPS.items).map((item, i) => readItem(item, i, problems)).filter(Boolean);
  return { ok: true, lecture: { kind: LECTURE_KIND, version: LECTURE_VERSION, title, items }, problems };
}
