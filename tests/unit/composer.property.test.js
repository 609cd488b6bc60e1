// The composer against anything: a pasted link from anyone's clipboard never throws and gives only
// values the panel's schema takes; any sequence of edits keeps every item once, in a list the
// lecture link carries unchanged.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { readPastedLink } from '../../src/compose/pastedLink.js';
import {
  addItem, draftToLecture, duplicateItem, emptyDraft, moveItem, moveItemTo, panelItem, questionItem, removeItem, textItem,
} from '../../src/compose/composerModel.js';
import { lectureFromCode, lectureToCode } from '../../src/lecture/lectureLink.js';
import { PANELS } from '../../src/panels/manifest.js';
import { panelSchema } from '../../src/panels/panelSchema.js';
import { parseValue } from '../../src/host/params.js';
import { QUESTIONS } from '../../src/homework/questions.js';
import { anyKey, anyText, anyValue, PROTOTYPE_NAMES } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

const panelId = fc.constantFrom(...PANELS.map((p) => p.id), 'no-such', ...PROTOTYPE_NAMES);
const piece = fc.oneof(anyText, anyKey, fc.constantFrom('panel', 'lock', 'hide', 'lecture', 'nT', 'spheres.nT', 'L1.', '%', '#', '&amp;', '"'));
/** Texts shaped like links: a page, pairs of pieces, a hash, an iframe snippet now and then. */
const linkLike = fc.tuple(fc.constantFrom('', 'https://x/index.html?', 'embed.html?panel=spheres&', 'index.html?lecture=', '<iframe src="embed.html?'),
  fc.array(fc.tuple(piece, piece), { maxLength: 8 }), fc.oneof(fc.constant(''), piece.map((p) => `#${p}`)))
  .map(([page, pairs, hash]) => `${page}${pairs.map(([k, v]) => `${k}=${v}`).join('&')}${hash}`);

describe('a pasted link', () => {
  it('never throws, and what it gives the panel is what the panel’s schema takes', () => {
    check(fc.property(fc.oneof(linkLike, anyText, anyValue), panelId, (text, id) => {
      const read = readPastedLink(text, id);
      expect(read.problems.every((p) => typeof p === 'string' && p.length > 0)).toBe(true);
      if (!read.ok) {
        expect(read.problems.length).toBeGreaterThan(0);
        return;
      }
      const schema = panelSchema(id);
      for (const [key, value] of Object.entries(read.state)) {
        expect(Object.hasOwn(schema, key), key).toBe(true);
        expect(parseValue(schema[key], value).ok, `${key}=${value}`).toBe(true);
      }
      for (const key of [...read.lock, ...read.hide]) expect(Object.hasOwn(schema, key)).toBe(true);
    }), 400);
  });
});

const anyItem = fc.oneof(
  fc.constantFrom(...PANELS.map((p) => p.id)).map(panelItem),
  fc.string({ minLength: 1, maxLength: 40 }).map((t) => textItem('', `x${t}`)),
  fc.constantFrom(...QUESTIONS.map((q) => q.id)).map((id) => questionItem(id)),
);
const edit = fc.oneof(
  anyItem.map((item) => ({ op: 'add', item })),
  fc.record({ op: fc.constant('move'), at: fc.nat(20), delta: fc.integer({ min: -3, max: 3 }) }),
  fc.record({ op: fc.constant('moveTo'), at: fc.nat(20), to: fc.integer({ min: -2, max: 25 }) }),
  fc.record({ op: fc.constant('duplicate'), at: fc.nat(20) }),
  fc.record({ op: fc.constant('remove'), at: fc.nat(20) }),
);

describe('edits to the list', () => {
  it('keep every item once, each key unique, and give a lecture the link carries unchanged', () => {
    check(fc.property(fc.array(edit, { maxLength: 30 }), (edits) => {
      let draft = emptyDraft('Fuzzed');
      for (const e of edits) {
        const key = draft.items[e.at % Math.max(1, draft.items.length)]?.key ?? 'none';
        const before = draft.items.length;
        if (e.op === 'add') draft = addItem(draft, e.item).draft;
        else if (e.op === 'move') draft = moveItem(draft, key, e.delta);
        else if (e.op === 'moveTo') draft = moveItemTo(draft, key, e.to);
        else if (e.op === 'duplicate') draft = duplicateItem(draft, key).draft;
        else draft = removeItem(draft, key);
        const expected = before + (e.op === 'add' || (e.op === 'duplicate' && before) ? 1 : e.op === 'remove' && before ? -1 : 0);
        expect(draft.items.length).toBe(expected);
      }
      expect(new Set(draft.items.map((i) => i.key)).size).toBe(draft.items.length);
      const { lecture, problems } = draftToLecture(draft);
      expect(problems).toEqual([]);
      expect(lecture.items).toHaveLength(draft.items.length);
      expect(lectureFromCode(lectureToCode(lecture))).toEqual({ ok: true, lecture, problems: [] });
    }), 150);
  });
});
