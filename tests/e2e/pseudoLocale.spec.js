// Every page, panel, dialog and notice in the pseudo-locales (docs/i18n.md): under ?lang=en-XA each
// catalogue message is accented, a third longer and ⟦bracketed⟧, so a word on screen, in an ARIA
// attribute or said by a live region outside brackets never went through the catalogue, and text
// that is cut, runs off the screen or lies on other text does not take a longer language. Under
// ?lang=ar-XB (right to left) the same layout must hold. One test per area and language; each
// lists every finding as “page — element: text”. Pages are shared: the embeds open in one page in
// turn, the lecture page mounts its panels section by section.
import { deflateSync } from 'fflate';
import { test, expect, labReady } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';
import { mirroredGeometry, pseudoAuditScript, textLayoutFaults, wordsOutsideCatalogue } from './pseudoAudit.js';


/**
 * Words from outside the lab, which no catalogue holds: a student's name and seed (from a hand-in),
 * a sheet's and a lecture's title and the lecturer's own headings and text (from their links); and
 * a hand-in's time, which Intl writes in the page's language.
 */
const OUTSIDE = ['.hw-name', '.hw-report-who', '.hw-seed', '.hw-seed-cell', '.hw-time', '.hw-sheet-head h1', '.site-title h1',
  '.lecture-own', '.cp-name-own', '.cp-preview'];

/**
 * Words inside a message that are no catalogue's, so stay unaccented: what this test brings in from
 * outside (the titles, headings, names and seeds of its sheet, class and lecture, the question ids a
 * sheet names, the bad link values and the fault it injects), a time's AM and PM as Intl writes them,
 * GLSL's precision qualifiers, the cosine and a speed's v_i, and the device and date of the GPU
 * results the speed-accuracy panel shows.
 */
const KNOWN = () => [
  SHEET.title, ...SHEET.items.map((item) => item.question), ...CLASS.flatMap((h) => [h.name, h.seed]),
  LECTURE.title, ...LECTURE.items.map((item) => item.heading ?? ''), 'nT=abc theme=mauve an injected fault',
  'AM PM mediump highp cos vi NVIDIA Dec',
].join(' ').match(/[A-Za-z]+/g);

/**
 * What keeps left to right in a right-to-left language: formulas and code, the pictures with labels
 * over their parts (the hero's three spheres, split and paired views), diagrams and plots drawn from
 * the left (rays, the prediction figure's plot, a histogram, colour scales, lil-gui's slider), and a
 * derivation set out in columns.
 */
const GEOMETRY = ['.katex', 'code', 'pre', '.sl-editor', '.stage', '.legend', '.twin-stage', '.cspec-stage', '.cspec-diagram',
  '.nm-stage', '.nm-legend', '.ar-svg', '.predict-svg', '.hw-columns', '.lil-slider', '.r0-steps'];

const LANGUAGES = [
  { lang: 'en-XA', words: true, rtl: false },
  { lang: 'ar-XB', words: false, rtl: true }, // the same words, right to left: only the layout is new
];

const code = (data) => Buffer.from(JSON.stringify(data)).toString('base64url');
const lectureCode = (lecture) => `L1.${Buffer.from(deflateSync(Buffer.from(JSON.stringify(lecture)), { level: 9 })).toString('base64url')}`;
// A question of each kind: predict (an angle on a figure), numeric (typed), choice (options).
const SHEET = { version: 1, title: 'Week 3', items: [{ question: 'brewster-predict' }, { question: 'exact-r' }, { question: 'metal-grazing' }] };
const handIn = (name, seed, answers) => ({
  kind: 'fresnel-lab-hand-in', version: 1, sheet: SHEET, seed, name, answers, attempts: answers.map(() => 1), time: '2026-11-10T10:00:00Z',
});
const CLASS = [
  handIn('Ann', 'twin', [40, '0.9', 'dark']), handIn('Ben', 'twin', [40, '0.9', 'dark']),
  handIn('Cy', 'c3', [56, '0.5', 'towards-white']), handIn('', 'd4', [null, null, null]),
];
const LECTURE = {
  kind: 'fresnel-lab-lecture', version: 1, title: 'Glass, both ways',
  items: [
    { type: 'panel', panel: 'spheres', state: { nT: 1.7 }, heading: 'Into the glass', text: 'Watch the *rim*: $R_0$ grows.' },
    { type: 'text', heading: 'Agenda', text: '1. Into the glass\n2. Out of it' },
    { type: 'question', question: 'brewster-predict', heading: 'Before Brewster' },
    { type: 'panel', panel: 'schlick', lock: ['nI'] },
  ],
};

/** Waits for a lab page's panels (a page in another language sets window.fresnelLab once its catalogue is in). */
async function ready(page) {
  await page.waitForFunction(() => window.fresnelLab?.ready);
  await labReady(page);
}
const twoFrames = (page) => page.evaluate(() => new Promise((resolve) => { requestAnimationFrame(() => requestAnimationFrame(resolve)); }));

/** The findings of one test: check() reads the page as it stands, done() fails on any. */
function audit(page, { lang, words, rtl }) {
  const findings = [];
  return {
    /** Reads `root` (a selector); said: also what live regions said and the page's title (once a page is done). */
    async check(label, { root = 'body', outside = OUTSIDE, said = root === 'body' } = {}) {
      // Formulas show their TeX source until KaTeX is here (ui/tex.js): read them typeset.
      await page.waitForFunction((r) => ![...document.querySelectorAll(r)]
        .some((e) => e.matches('[aria-busy="true"]') || e.querySelector('[aria-busy="true"]')), root);
      if (words) {
        const found = await wordsOutsideCatalogue(page, { root, outside, known: KNOWN(), live: said });
        for (const f of found) findings.push({ page: label, ...f, kind: 'words' });
      }
      for (const f of await textLayoutFaults(page, { root })) findings.push({ page: label, ...f, kind: 'layout' });
      if (rtl) for (const f of await mirroredGeometry(page, GEOMETRY)) findings.push({ page: label, ...f, kind: 'layout' });
    },
    done() {
      const seen = new Set();
      const unique = findings.map((f) => ({ ...f, line: `${f.page} — ${f.where}: ${f.text}` }))
        .filter((f) => !seen.has(f.line) && seen.add(f.line));
      expect(unique.map((f) => f.line), `?lang=${lang}: words outside the catalogue, or text that does not fit`).toEqual([]);
    },
  };
}

for (const { lang, words, rtl } of LANGUAGES) {
  test.describe(`?lang=${lang}`, () => {
    test.beforeEach(async ({ page }) => { await page.context().addInitScript(pseudoAuditScript); });

    test('the lecture page, every panel mounted in turn, with the audio trace on', async ({ page }) => {
      test.setTimeout(120_000);
      const a = audit(page, { lang, words, rtl });
      await page.goto(`./?lang=${lang}&audio=1`);
      await ready(page);
      await a.check('lecture page');
      for (const { id } of PANELS) {
        await page.locator(`#${id}`).evaluate((section) => section.scrollIntoView({ block: 'start' }));
        await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].mounted, id), { message: `${id} mounted` }).toBe(true);
        await twoFrames(page);
        await a.check(`lecture page ${id}`, { root: `#${id}` });
      }
      await a.check('lecture page, every panel seen', { root: 'header', said: true });
      a.done();
    });

    test('every panel\'s embed, one page in turn, and the words of the audio trace', async ({ page }) => {
      test.setTimeout(120_000);
      const a = audit(page, { lang, words, rtl });
      for (const { id, animates } of PANELS) {
        const still = `${animates ? `&${animates}=false` : ''}${id === 'normal-mips' ? '&truth=false' : ''}`;
        await page.goto(`embed.html?panel=${id}${still}&lang=${lang}`);
        await ready(page);
        await twoFrames(page);
        await a.check(`embed ${id}`);
      }
      // The trace, turned on by its key on a plot, from glass into air: past Brewster's angle, past the
      // critical angle into total internal reflection, then the whole curve played.
      await page.goto(`embed.html?panel=polarization&nI=1.5&nT=1&lang=${lang}`);
      await ready(page);
      await page.keyboard.press('a');
      await expect(page.locator('.trace-body')).toBeVisible();
      for (let i = 0; i < 43; i += 1) await page.keyboard.press('ArrowRight');
      await page.keyboard.press(' ');
      expect(await page.evaluate(() => window.fresnelLab.audio.log().map((s) => s.cues).flat())).toEqual(['brewster', 'critical', 'brewster', 'critical']);
      await a.check('embed polarization, audio trace on');
      a.done();
    });

    test('the homework page, a sheet with a question of each kind, and handing in without a name', async ({ page }) => {
      test.setTimeout(90_000);
      const a = audit(page, { lang, words, rtl });
      await page.goto(`homework.html?lang=${lang}`);
      await expect(page.locator('.hw-composer')).toBeVisible();
      await page.locator('#pick-brewster-predict').check();
      await a.check('homework page (lecturer)');
      await page.goto(`homework.html?sheet=${code(SHEET)}&lang=${lang}`);
      await expect(page.locator('#question-3')).toBeVisible();
      await a.check('sheet (student), unanswered');
      await page.locator('#question-1 .hw-commit').click(); // the prediction: the marker's start, 45°
      await page.locator('#question-2 input').fill('0.5');
      await page.locator('#question-2 .hw-commit').click();
      await page.locator('#question-3 .hw-option input').first().check();
      await page.locator('#question-3 .hw-commit').click();
      await expect(page.locator('#question-3 .hw-result')).not.toBeEmpty();
      await page.locator('.hw-send').click(); // no name given: asked first
      await expect(page.locator('.hw-anyway')).toBeVisible();
      await a.check('sheet (student), answered and asked before handing in');
      a.done();
    });

    test('the class view of a small class, a report and a question shown to the class', async ({ page }) => {
      test.setTimeout(90_000);
      const a = audit(page, { lang, words, rtl });
      await page.goto(`homework.html?lang=${lang}`);
      const section = page.locator('.hw-class');
      await section.locator('input[type="text"]').fill(`homework.html?sheet=${code(SHEET)}`);
      await section.locator('textarea').fill(CLASS.map((h) => `FLH1.${code(h)}`).join('\n'));
      await section.locator('.hw-primary').click();
      await expect(page.locator('.hw-gradebook .hw-body [role="row"]')).toHaveCount(CLASS.length, { timeout: 60_000 });
      await page.evaluate(() => window.fresnelLab.homework.classView.table.ready);
      await a.check('class view');
      await page.locator('.hw-gradebook .hw-details').first().click();
      await expect(page.locator('.hw-student-dialog')).toBeVisible();
      await a.check('class view, a student\'s report', { root: '.hw-student-dialog' });
      await page.keyboard.press('Escape');
      await page.locator('.hw-show-class').nth(1).click();
      await expect(page.locator('.hw-show-dialog')).toBeVisible();
      await a.check('class view, a question shown to the class', { root: '.hw-show-dialog' });
      a.done();
    });

    test('the composer with a panel, a text and a question, and the lecture it composes', async ({ page }) => {
      test.setTimeout(90_000);
      const a = audit(page, { lang, words, rtl });
      const lecture = lectureCode(LECTURE);
      await page.goto(`compose.html?lecture=${lecture}&lang=${lang}`);
      await expect(page.locator('.cp-item')).toHaveCount(LECTURE.items.length);
      await a.check('composer');
      await page.goto(`./?lecture=${lecture}&lang=${lang}`);
      await ready(page);
      const keys = await page.locator('main > section').evaluateAll((sections) => sections.map((s) => s.id));
      expect(keys).toHaveLength(LECTURE.items.length);
      for (const key of keys) {
        await page.locator(`#${key}`).evaluate((s) => s.scrollIntoView({ block: 'start' }));
        const host = await page.evaluate((k) => Boolean(window.fresnelLab.hosts[k]), key);
        if (host) await expect.poll(() => page.evaluate((k) => window.fresnelLab.hosts[k].mounted, key), { message: `${key} mounted` }).toBe(true);
        await twoFrames(page);
        await a.check(`composed lecture ${key}`, { root: `#${key}` });
      }
      await a.check('composed lecture');
      a.done();
    });

    test.describe('notices', () => {
      test.use({ allowedErrors: /an injected fault/ });

      test('a bad value in a link, a fault on the page and one in a panel', async ({ page }) => {
        const a = audit(page, { lang, words, rtl });
        await page.goto(`embed.html?panel=schlick&nT=abc&theme=mauve&lang=${lang}`);
        await ready(page);
        await expect(page.locator('.notice')).toHaveCount(2);
        await a.check('embed with bad link values');
        await page.goto(`./?nT=abc&lang=${lang}`);
        await ready(page);
        await expect(page.locator('section[data-panel="spheres"] .notice')).toBeVisible();
        await page.evaluate(() => { setTimeout(() => { throw new Error('an injected fault'); }, 0); });
        await expect(page.locator('main > .notice-error')).toBeVisible();
        await page.evaluate(() => {
          window.fresnelLab.panels.spheres.update = () => { throw new Error('an injected fault'); };
          window.fresnelLab.hosts.spheres.set({ nT: 2 });
        });
        await expect(page.locator('#spheres .panel-fault')).toBeVisible();
        await a.check('lecture page with a bad link value and faults', { root: 'header, main > .notice, #spheres' });
        a.done();
      });
    });
  });
}
