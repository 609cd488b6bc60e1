// The offline lecture export: the single-file lecture page with the lecture as a JSON data element.
// The element parses back to the lecture as readLecture gives it, whatever its text holds; a second
// export replaces the first; the page's scripts, and so the hashes its Content-Security-Policy
// allows, are unchanged.
import { describe, expect, it } from 'vitest';
import { existsSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import fc from 'fast-check';
import { LECTURE_ELEMENT_ID, lectureDataJson, offlineLectureHtml, offlineLectureZip } from '../../src/lecture/offlineExport.js';
import { strFromU8, unzipSync } from 'fflate';
import { LECTURE_KIND, readLecture } from '../../src/lecture/readLecture.js';
import { contentSecurityPolicy, inlineTexts } from '../../scripts/contentSecurityPolicy.js';
import { QUESTIONS } from '../../src/homework/questions.js';
import { check } from './fuzzConfig.js';

const HOSTILE = ['</script><script>alert(1)</script>', '</SCRIPT ><script>alert(1)</script>', '<!--<script>', '<!-- -->', '</scri\u0000pt>',
  '<img src=x onerror=alert(1)>', '"><svg onload=alert(1)>', '\u2028\u2029', '</head><body>', '<title>x</title>', "'; alert(1); //"];

// A page shaped like dist/offline/index.html: charset, the policy meta, a title, one inline module
// script (whose text holds markup-like strings, as a bundle may), then the body.
const bundle = 'const a = "</head>"; const b = "<title>no</title>"; document.title = `x${a}${b}`;';
const PAGE = `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta http-equiv="Content-Security-Policy" content="${contentSecurityPolicy({ singleFile: true, scripts: [bundle], styles: ['p{}'] })}">
  <title>Fresnel Lab: mipmapping normal maps and Fresnel reflection</title>
  <script type="module" crossorigin>${bundle}</script>
  <style>p{}</style>
</head>
<body>
  <main></main>
</body>
</html>
`;

const lecture = (over = {}) => ({
  kind: LECTURE_KIND, version: 1, title: 'Glass, twice',
  items: [
    { type: 'text', heading: 'Agenda', text: '- air → glass\n- glass → air' },
    { type: 'panel', panel: 'spheres', state: { nT: 1.5 }, heading: 'Into glass' },
    { type: 'panel', panel: 'spheres', state: { nI: 1.5, nT: 1 }, lock: ['nI'], text: 'Out of the glass: past $\\theta_c$ all reflects.' },
    { type: 'question', question: QUESTIONS[0].id, seed: 'room' },
  ],
  ...over,
});

/** The data elements in a page: [openTag, text]; a text runs to the first </script, as a browser reads it. */
function dataElements(html) {
  return [...html.matchAll(/<script\b([^>]*)>([\s\S]*?)<\/script/gi)]
    .filter(([, attrs]) => attrs.includes(LECTURE_ELEMENT_ID)).map(([, attrs, text]) => [attrs, text]);
}

function readBack(html) {
  const found = dataElements(html);
  expect(found).toHaveLength(1);
  const [attrs, text] = found[0];
  expect(attrs).toBe(` type="application/json" id="${LECTURE_ELEMENT_ID}"`);
  expect(text).not.toContain('<');
  return JSON.parse(text);
}

describe('the offline lecture page', () => {
  it('holds the lecture, as readLecture gives it, in one data element before the page\'s first script', () => {
    const html = offlineLectureHtml(PAGE, { ...lecture(), items: [...lecture().items, { type: 'panel', panel: 'nope' }] });
    expect(readBack(html)).toEqual(readLecture(lecture()).lecture); // the unknown panel is not written
    const at = html.indexOf(`id="${LECTURE_ELEMENT_ID}"`);
    expect(at).toBeGreaterThan(html.indexOf('Content-Security-Policy'));
    expect(at).toBeLessThan(html.indexOf('<script type="module"'));
    expect(html).toContain(`\n  <script type="application/json" id="${LECTURE_ELEMENT_ID}">`);
    expect(html).toContain('</script>\n  <script type="module" crossorigin>');
  });

  it('carries the lecture\'s language in its data element, and its title in the page\'s title as the build writes it', () => {
    const built = PAGE.replace('<title>', '<title data-i18n="page.title">'); // the pages' words come from the catalogue
    const html = offlineLectureHtml(built, lecture({ lang: 'es' }));
    expect(readBack(html).lang).toBe('es');
    expect(html).toContain('<title>Glass, twice: Fresnel Lab</title>');
    expect(html).not.toContain('mipmapping normal maps');
  });

  it('changes nothing the page\'s policy covers: the same inline scripts and styles, so the same hashes', () => {
    const html = offlineLectureHtml(PAGE, lecture({ title: HOSTILE[0] }));
    expect(inlineTexts(html)).toEqual(inlineTexts(PAGE)); // the JSON block is data, which script-src does not govern
    const policy = /http-equiv="Content-Security-Policy" content="([^"]*)"/.exec(html)[1];
    expect(policy).toBe(contentSecurityPolicy({ singleFile: true, ...inlineTexts(html) }));
    expect(html.replace(/\n {2}<script type="application\/json"[^>]*>[^<]*<\/script>/, '').replace(/<title>[^<]*<\/title>/, ''))
      .toBe(PAGE.replace(/<title>[^<]*<\/title>/, ''));
  });

  it('a hostile title, heading or text stays data: the element ends where it should and parses back', () => {
    for (const bad of HOSTILE) {
      const items = [{ type: 'text', heading: bad, text: bad }, { type: 'panel', panel: 'schlick', heading: bad, text: bad }];
      const data = lecture({ title: bad, items });
      const html = offlineLectureHtml(PAGE, data);
      expect(readBack(html)).toEqual(readLecture(data).lecture);
      expect(inlineTexts(html).scripts).toEqual([bundle]); // no script was opened by the text
      const entities = { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' };
      expect(html).toContain(`<title>${`${readLecture(data).lecture.title}: Fresnel Lab`.replace(/[&<>"']/g, (c) => entities[c])}</title>`);
    }
  });

  it('any lecture: the element parses back to it and nothing in it can end the element', () => {
    const text = fc.oneof(fc.string({ unit: 'grapheme', maxLength: 60 }), fc.constantFrom(...HOSTILE),
      fc.array(fc.constantFrom(...HOSTILE, '<', '/', 'script', '!--', ' ', '\\u003c'), { maxLength: 8 }).map((p) => p.join('')));
    const item = fc.oneof(
      fc.record({ type: fc.constant('text'), heading: text, text }),
      fc.record({ type: fc.constant('panel'), panel: fc.constantFrom('schlick', 'spheres', 'metals'), heading: text, text },
        { requiredKeys: ['type', 'panel'] }),
    );
    const anyLecture = fc.record({
      kind: fc.constant(LECTURE_KIND), version: fc.constant(1), title: text, items: fc.array(item, { maxLength: 6 }),
    });
    check(fc.property(anyLecture, (data) => {
      const html = offlineLectureHtml(PAGE, data);
      expect(readBack(html)).toEqual(readLecture(data).lecture);
      expect(inlineTexts(html).scripts).toEqual([bundle]);
    }), 200);
  });

  it('a second export replaces the first: one element, and the page as if exported once', () => {
    const first = offlineLectureHtml(PAGE, lecture({ title: 'First' }));
    const second = offlineLectureHtml(first, lecture({ title: 'Second' }));
    expect(dataElements(second)).toHaveLength(1);
    expect(second).toBe(offlineLectureHtml(PAGE, lecture({ title: 'Second' })));
    expect(readBack(second).title).toBe('Second');
  });

  it('writes every < of the JSON as \\u003c, which JSON.parse reads back as <', () => {
    const json = lectureDataJson({ title: '</script><!--' });
    expect(json).toBe('{"title":"\\u003c/script>\\u003c!--"}');
    expect(JSON.parse(json).title).toBe('</script><!--');
  });

  it('refuses what is no lecture or no page, with a reason', () => {
    expect(() => offlineLectureHtml(PAGE, { kind: 'x' })).toThrow(/no lecture/);
    expect(() => offlineLectureHtml(PAGE, null)).toThrow(/no lecture/);
    expect(() => offlineLectureHtml('not a page', lecture())).toThrow(/not an HTML page/);
    expect(() => offlineLectureHtml(undefined, lecture())).toThrow(/not an HTML page/);
  });

  // The page the build writes, when there is one (npm run build): its policy still holds.
  const built = resolve(import.meta.dirname, '../../dist/offline/index.html');
  it.skipIf(!existsSync(built))('the built offline lecture page keeps its scripts and its policy, and holds the lecture', () => {
    const page = readFileSync(built, 'utf8');
    const html = offlineLectureHtml(page, lecture({ title: HOSTILE[0] }));
    expect(inlineTexts(html)).toEqual(inlineTexts(page));
    expect(readBack(html)).toEqual(readLecture(lecture({ title: HOSTILE[0] })).lecture);
    expect(html.length - page.length).toBeLessThan(2000);
  });
});

describe('the offline lecture as one download', () => {
  it('is a .zip of one folder: the lecture, the embed page its frames open, and the icon', async () => {
    const embed = '<!doctype html><html><head><title>embed</title></head><body></body></html>';
    const zip = unzipSync(await offlineLectureZip({ index: PAGE, embed, favicon: '<svg/>' }, lecture(), 'glass-twice'));
    expect(Object.keys(zip).sort()).toEqual(['glass-twice/', 'glass-twice/embed.html', 'glass-twice/favicon.svg', 'glass-twice/index.html']);
    expect(strFromU8(zip['glass-twice/index.html'])).toBe(offlineLectureHtml(PAGE, lecture()));
    expect(strFromU8(zip['glass-twice/embed.html'])).toBe(embed);
  });
  it('refuses an embed page that is no HTML page, and a lecture with nothing usable', async () => {
    await expect(offlineLectureZip({ index: PAGE, embed: 'not found' }, lecture(), 'x')).rejects.toThrow(TypeError);
    await expect(offlineLectureZip({ index: PAGE, embed: PAGE }, { kind: 'nope' }, 'x')).rejects.toThrow(TypeError);
  });
});
