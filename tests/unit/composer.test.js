// The lecture composer's model: a list of items added, moved, copied and removed by key; the
// lecture it gives reads back through the lecture link unchanged; links pasted as start states
// are read with the panel's schema, and what is refused is named.
import { describe, expect, it } from 'vitest';
import {
  addItem, draftData, draftFromLecture, draftToLecture, duplicateItem, emptyDraft, itemName, moveItem, moveItemTo,
  panelItem, questionItem, removeItem, setLanguage, setTitle, textItem, updateItem,
} from '../../src/compose/composerModel.js';
import { readPastedLink } from '../../src/compose/pastedLink.js';
import { panelCatalogue, plainText, questionCatalogue, shortText } from '../../src/compose/catalogue.js';
import { DRAFT_KEY, loadDraft, saveDraft } from '../../src/compose/draftStore.js';
import { lectureFromCode, lectureToCode } from '../../src/lecture/lectureLink.js';
import { LECTURE_CAPS } from '../../src/lecture/readLecture.js';
import { PANELS } from '../../src/panels/manifest.js';
import { QUESTIONS } from '../../src/homework/questions.js';

/** A draft of several items, built one call at a time: { draft, keys }. */
function build(...items) {
  let draft = emptyDraft('Optics, my way');
  const keys = [];
  for (const item of items) {
    const added = addItem(draft, item);
    draft = added.draft;
    keys.push(added.key);
  }
  return { draft, keys };
}
const order = (draft) => draft.items.map((i) => i.key);

describe('the composer’s list', () => {
  it('adds items with keys of their own, the same panel twice', () => {
    const { draft, keys } = build(panelItem('spheres'), panelItem('spheres'), textItem('Agenda', 'First this'));
    expect(new Set(keys).size).toBe(3);
    expect(draft.items.map((i) => i.type === 'panel' ? i.panel : i.type)).toEqual(['spheres', 'spheres', 'text']);
    // Each item is its own: changing one leaves the other panel as it was.
    const changed = updateItem(draft, keys[1], { state: { nT: 1 } });
    expect(changed.items[0].state).toEqual({});
    expect(changed.items[1].state).toEqual({ nT: 1 });
    expect(draft.items[1].state).toEqual({}); // pure: the old draft is unchanged
  });

  it('moves an item up, down and to a place, clamped to the list', () => {
    const { draft, keys: [a, b, c] } = build(panelItem('schlick'), textItem('', 'x'), panelItem('metals'));
    expect(order(moveItem(draft, c, -1))).toEqual([a, c, b]);
    expect(order(moveItem(draft, a, 1))).toEqual([b, a, c]);
    expect(order(moveItem(draft, a, -1))).toEqual([a, b, c]);
    expect(order(moveItem(draft, c, 5))).toEqual([a, b, c]);
    expect(order(moveItemTo(draft, a, 2))).toEqual([b, c, a]);
    expect(order(moveItemTo(draft, c, 0))).toEqual([c, a, b]);
    expect(moveItemTo(draft, 'no-such', 0)).toBe(draft);
  });

  it('duplicates an item right after itself with a new key, its lists its own', () => {
    const start = build(panelItem('spheres'), textItem('', 'y'));
    const withState = updateItem(start.draft, start.keys[0], { state: { nT: 1.2 }, lock: ['nI'], heading: 'Air to glass' });
    const { draft, key } = duplicateItem(withState, start.keys[0]);
    expect(order(draft)).toEqual([start.keys[0], key, start.keys[1]]);
    expect(draft.items[1]).toMatchObject({ type: 'panel', panel: 'spheres', state: { nT: 1.2 }, lock: ['nI'], heading: 'Air to glass' });
    expect(draft.items[1].lock).not.toBe(draft.items[0].lock);
    expect(draft.items[1].state).not.toBe(draft.items[0].state);
  });

  it('removes an item by key', () => {
    const { draft, keys: [a, b, c] } = build(panelItem('schlick'), questionItem('critical-angle'), textItem('', 'z'));
    expect(order(removeItem(draft, b))).toEqual([a, c]);
    expect(removeItem(draft, 'no-such').items).toEqual(draft.items);
  });

  it('adds no more items than a lecture may hold', () => {
    let draft = emptyDraft();
    for (let i = 0; i < LECTURE_CAPS.items; i++) draft = addItem(draft, textItem('', `${i}`)).draft;
    const over = addItem(draft, textItem('', 'one more'));
    expect(over.key).toBeNull();
    expect(over.draft.items).toHaveLength(LECTURE_CAPS.items);
  });

  it('names items in plain text for the list and the announcements', () => {
    expect(itemName({ ...panelItem('spheres'), key: 'k' })).toBe('Exact Fresnel vs Schlick\'s approximation');
    expect(itemName({ ...panelItem('spheres'), heading: ' Mine ', key: 'k' })).toBe('Mine (Exact Fresnel vs Schlick\'s approximation)');
    expect(itemName({ ...questionItem('critical-angle'), heading: 'Ask', key: 'k' })).toBe('Ask (Question on “The ratio of reflection '
      + 'to refraction depends on the angle”)');
    expect(itemName({ ...textItem('', 'Agenda\nthen more'), key: 'k' })).toBe('Agenda');
    expect(itemName({ ...questionItem('critical-angle'), key: 'k' })).toContain('Question on');
  });
});

describe('the lecture a draft gives', () => {
  it('a panel twice with two states, reordered, a text and a question: round trip through the link', () => {
    let { draft, keys } = build(panelItem('spheres'), panelItem('schlick'), textItem('Agenda', '- *exact*\n- $R_0$'), questionItem('critical-angle', 'room 2'));
    draft = updateItem(draft, keys[0], { state: { nI: 1, nT: 2 }, heading: 'Air to glass', text: 'Watch the **rim**.' });
    const copy = duplicateItem(draft, keys[0]);
    draft = updateItem(copy.draft, copy.key, { state: { nI: 1.5, nT: 1 }, heading: 'Glass to air', lock: ['nI'], hide: ['kd'] });
    draft = moveItemTo(setTitle(draft, 'Optics, my way'), keys[2], 0);
    const { lecture, problems } = draftToLecture(draft);
    expect(problems).toEqual([]);
    expect(lecture.items.map((i) => i.type === 'panel' ? `${i.panel}:${i.heading}` : i.type))
      .toEqual(['text', 'spheres:Air to glass', 'spheres:Glass to air', 'schlick:undefined', 'question']);
    // A value equal to its default is not stored (nI = 1 is the hero's default).
    expect(lecture.items[1].state).toEqual({ nT: 2 });
    expect(lecture.items[2]).toMatchObject({ state: { nI: 1.5, nT: 1 }, lock: ['nI'], hide: ['kd'] });
    expect(lecture.items[4]).toEqual({ type: 'question', question: 'critical-angle', seed: 'room 2' });
    const back = lectureFromCode(lectureToCode(lecture));
    expect(back).toEqual({ ok: true, lecture, problems: [] });
    // And back into the composer: the same lecture again.
    expect(draftToLecture(draftFromLecture(back.lecture)).lecture).toEqual(lecture);
  });

  it('what readLecture would leave out is named by the item’s place', () => {
    const { draft } = build(panelItem('schlick'), textItem('', '   '), questionItem('no-such-question'));
    const { lecture, problems } = draftToLecture(draft);
    expect(lecture.items).toEqual([{ type: 'panel', panel: 'schlick' }]);
    expect(problems.join('\n')).toMatch(/Item 2 is a text item without text/);
    expect(problems.join('\n')).toMatch(/Item 3: no-such-question is no question/);
  });

  it('leaves empty fields out of the data it keeps, and writes a new lecture in the page’s language', () => {
    const { draft } = build(panelItem('schlick'));
    expect(draftData(draft)).toEqual({
      kind: 'fresnel-lab-lecture', version: 1, title: 'Optics, my way', lang: 'en', items: [{ type: 'panel', panel: 'schlick' }],
    });
  });

  it('keeps an opened lecture’s language on a page in another, until the lecturer changes it', () => {
    // The page speaks English here (Node has no other catalogue loaded): a Spanish lecture stays Spanish.
    const spanish = { kind: 'fresnel-lab-lecture', version: 1, title: 'Óptica', lang: 'es', items: [{ type: 'panel', panel: 'schlick' }] };
    const draft = draftFromLecture(spanish);
    expect(draft.lang).toBe('es');
    expect(draftData(draft).lang).toBe('es');
    expect(draftToLecture(updateItem(draft, draft.items[0].key, { heading: 'Schlick' })).lecture.lang).toBe('es');
    expect(lectureFromCode(lectureToCode(draftToLecture(draft).lecture)).lecture.lang).toBe('es');
    // Changed only by the lecturer's choice; a lecture that carries none takes the page's.
    expect(draftToLecture(setLanguage(draft, 'en')).lecture.lang).toBe('en');
    expect(draftFromLecture({ ...spanish, lang: undefined }).lang).toBe('en');
  });
});

describe('a link pasted as a panel’s start state', () => {
  it('reads the lecture page’s link of a panel (prefixed keys) and passes over the other panels’ values', () => {
    const read = readPastedLink('https://lab.example/index.html?nT=2&schlick.nT=1.8&schlick.nI=1&metals.metal=gold#schlick', 'schlick');
    expect(read).toMatchObject({ ok: true, source: 'lecture', state: { nT: 1.8, nI: 1 }, problems: [] });
  });

  it('reads the hero’s unprefixed keys', () => {
    expect(readPastedLink('index.html?nT=2.4&kd=00ff00#spheres', 'spheres')).toMatchObject({ ok: true, state: { nT: 2.4, kd: '#00ff00' } });
  });

  it('reads an embed link with its locks and hidden controls, and the embed snippet', () => {
    const link = 'http://x/embed.html?panel=spheres&nT=1.33&lock=nI,nT&hide=kd&theme=light';
    expect(readPastedLink(link, 'spheres')).toMatchObject({ ok: true, source: 'embed', state: { nT: 1.33 }, lock: ['nI', 'nT'], hide: ['kd'], problems: [] });
    const snippet = '<iframe src="https://x/embed.html?panel=spheres&amp;nI=1.5&amp;nT=1" width="960"></iframe>';
    expect(readPastedLink(snippet, 'spheres')).toMatchObject({ ok: true, state: { nI: 1.5, nT: 1 } });
  });

  it('names every refused key and value, and keeps the rest', () => {
    const read = readPastedLink('embed.html?panel=spheres&nT=99&bogus=1&constructor=2&kd=nope&lightAz=20&lock=nT,toString', 'spheres');
    expect(read.ok).toBe(true);
    expect(read.state).toEqual({ lightAz: 20 });
    expect(read.lock).toEqual(['nT']);
    const said = read.problems.join('\n');
    for (const name of ['nT=99', 'bogus', 'constructor', 'kd=nope', 'toString']) expect(said).toContain(name);
  });

  it('refuses a link of another panel, naming both', () => {
    const embed = readPastedLink('embed.html?panel=metals&metal=gold', 'schlick');
    expect(embed.ok).toBe(false);
    expect(embed.problems[0]).toMatch(/Fresnel reflection and materials|metals/i);
    expect(readPastedLink('index.html?metals.metal=gold#metals', 'schlick').ok).toBe(false);
  });

  it('reads a composed lecture’s link: its first item of the panel', () => {
    const lecture = { kind: 'fresnel-lab-lecture', version: 1, title: 'T', items: [{ type: 'panel', panel: 'schlick', state: { nT: 2 }, lock: ['nT'] }] };
    expect(readPastedLink(`https://x/index.html?lecture=${lectureToCode(lecture)}`, 'schlick')).toMatchObject({ ok: true, source: 'composed', state: { nT: 2 }, lock: ['nT'] });
    expect(readPastedLink(`index.html?lecture=${lectureToCode(lecture)}`, 'spheres').ok).toBe(false);
  });

  it('reads a composed lecture’s panel link: the item its hash names, with the values under that item’s keys', () => {
    const lecture = {
      kind: 'fresnel-lab-lecture', version: 1, title: 'T',
      items: [{ type: 'panel', panel: 'spheres', state: { nT: 2 } }, { type: 'text', text: 'x' },
        { type: 'panel', panel: 'spheres', state: { nI: 1.5, nT: 1 }, lock: ['nI'] }],
    };
    const code = lectureToCode(lecture);
    // The second hero's link: its keys under spheres--2., the first hero's unprefixed ones passed over.
    const second = readPastedLink(`https://x/index.html?lecture=${code}&nT=2.2&spheres--2.kd=00ff00&spheres--2.nope=1#spheres--2`, 'spheres');
    expect(second).toMatchObject({ ok: true, state: { nI: 1.5, nT: 1, kd: '#00ff00' }, lock: ['nI'] });
    expect(second.problems.join('\n')).toContain('nope');
    expect(readPastedLink(`index.html?lecture=${code}&nT=2.2#spheres`, 'spheres')).toMatchObject({ ok: true, state: { nT: 2.2 } });
    expect(readPastedLink(`index.html?lecture=${code}#text--2`, 'spheres')).toMatchObject({ ok: false, problems: [expect.stringContaining('text item')] });
  });

  it('reads bare pairs and refuses what is not a link', () => {
    expect(readPastedLink('nT=1.7', 'schlick')).toMatchObject({ ok: true, state: { nT: 1.7 } });
    expect(readPastedLink('', 'schlick').ok).toBe(false);
    expect(readPastedLink('x', 'no-such-panel').ok).toBe(false);
    expect(readPastedLink('a'.repeat(200_000), 'schlick').ok).toBe(false);
  });
});

describe('the catalogue', () => {
  it('gives every panel by title and lede as plain text, and every question of the bank', () => {
    const panels = panelCatalogue();
    expect(panels.map((p) => p.id)).toEqual(PANELS.map((p) => p.id));
    for (const p of panels) {
      expect(p.lede).not.toMatch(/<|&[a-z]+;/);
      expect(p.lede.length).toBeGreaterThan(20);
    }
    expect(questionCatalogue().flatMap((g) => g.questions.map((q) => q.id)).sort()).toEqual(QUESTIONS.map((q) => q.id).sort());
  });

  it('reads HTML as text', () => {
    expect(plainText('k<sub>d</sub> &amp; <em>F</em> &lt;script&gt; &#x3b8; &bogus;')).toBe('k_d & F <script> θ &bogus;');
    expect(shortText('One. Two. Three.', 10)).toBe('One. Two.');
    expect(shortText('One two three four', 12)).toBe('One two…');
  });
});

describe('the work kept in the browser', () => {
  const memory = () => {
    const kept = new Map();
    return { getItem: (k) => kept.get(k) ?? null, setItem: (k, v) => kept.set(k, String(v)), removeItem: (k) => kept.delete(k), kept };
  };

  it('comes back as it was saved', () => {
    const storage = memory();
    const { draft } = build(panelItem('schlick'), textItem('Agenda', 'x'));
    expect(saveDraft(draftData(draft), storage)).toBe(true);
    expect(loadDraft(storage)).toEqual({ lecture: draftToLecture(draft).lecture, problems: [] });
  });

  it('is read as untrusted: damaged, foreign or refused storage is named, never used', () => {
    const storage = memory();
    expect(loadDraft(storage)).toEqual({ lecture: null, problems: [] });
    storage.kept.set(DRAFT_KEY, '{not json');
    expect(loadDraft(storage).problems[0]).toMatch(/damaged/);
    storage.kept.set(DRAFT_KEY, JSON.stringify({ kind: 'other' }));
    expect(loadDraft(storage).lecture).toBeNull();
    storage.kept.set(DRAFT_KEY, JSON.stringify({ kind: 'fresnel-lab-lecture', version: 1, title: 'x', items: [{ type: 'panel', panel: '__proto__' }] }));
    expect(loadDraft(storage)).toMatchObject({ lecture: { items: [] }, problems: [expect.stringContaining('__proto__')] });
    const refusing = { getItem: () => { throw new Error('denied'); }, setItem: () => { throw new Error('denied'); } };
    expect(loadDraft(refusing).problems[0]).toMatch(/refuses/);
    expect(saveDraft({}, refusing)).toBe(false);
  });
});
