// The shader lab as a student uses it: reference answers pass every criterion through the panel,
// a compile error is marked at the student's line, a loop is refused before the GPU sees it, the
// code round-trips through the link, typing in the editor grades, and homework mode hides the
// reference answers.
import { test, expect, openLab, labReady } from './fixtures.js';
import { EXERCISE_IDS } from '../../src/panels/shader-lab/exercises.js';
import { deflateSync } from 'fflate';
import { encodeCode, useDeflate } from '../../src/panels/shader-lab/codeCodec.js';

useDeflate((bytes) => deflateSync(bytes, { level: 9 })); // as the panel's module does

const embed = (query = '') => `./embed.html?panel=shader-lab${query}`;
const lab = (page, fn, arg) => page.evaluate(fn, arg);
const states = (page) => page.locator('.sl-criterion .sl-state');

test('every exercise\'s reference answer passes every criterion in the panel', async ({ page }) => {
  test.setTimeout(120_000);
  await openLab(page, embed());
  for (const id of EXERCISE_IDS) {
    await lab(page, (ex) => window.fresnelLab.hosts['shader-lab'].set({ exercise: ex }), id);
    await page.getByRole('button', { name: 'Show a reference answer' }).click();
    await expect.poll(async () => [...new Set(await states(page).allTextContents())], { message: id }).toEqual(['passed']);
    await expect(page.locator('.sl-summary')).toHaveText(/^(\d+) of \1 criteria pass\./);
    await expect(page.locator('.sl-spheres canvas')).toBeVisible();
  }
  // The conductor has no (θ, n_i/n_t) map; the dielectric exercises do, beside the reference's.
  await expect(page.locator('.st-maps')).toBeHidden();
  await lab(page, () => window.fresnelLab.hosts['shader-lab'].set({ exercise: 'exact' }));
  await expect(page.locator('.st-maps')).toBeVisible();
});

test('a compile error is marked at the student\'s line; a loop is refused before the GPU sees it', async ({ page }) => {
  await openLab(page, embed('&exercise=exact'));
  const broken = 'float fresnel(float cosTheta, float nI, float nT) {\n  float m = nI / nT;\n'
    + '  float g = sqrt(1.0 - m * m + c * c);\n  return g;\n}';
  await lab(page, (code) => window.fresnelLab.hosts['shader-lab'].set({ code }), broken);
  await expect(page.locator('.sl-errors li').first()).toHaveText(/^Line 3: 'c'.*undeclared identifier/);
  await expect(page.locator('.cm-lintRange-error')).toHaveText('  float g = sqrt(1.0 - m * m + c * c);');
  await expect(states(page)).toHaveText(['not graded', 'not graded']);
  // No empty lines from the log.
  for (const text of await page.locator('.sl-errors li').allTextContents()) expect(text).toMatch(/^Line \d+: \S/);
  await expect(page.locator('.panel-description')).toContainText('not graded; line 3:');
  const loop = 'float fresnel(float c, float a, float b) {\n  while (true) {}\n  return 0.0;\n}';
  await lab(page, (code) => window.fresnelLab.hosts['shader-lab'].set({ code }), loop);
  await expect(page.locator('.sl-errors li').first()).toHaveText(/^Line 2: Loops are refused here/);
});

test('the code round-trips through the link, compact, and typing in the editor grades', async ({ page }) => {
  test.setTimeout(120_000); // the lecture page: the panels around it mount too
  const code = 'float fresnel(float cosTheta, float nI, float nT) {\n  return 1.0; // everything reflects\n}';
  await openLab(page, `./?shader-lab.exercise=tir&shader-lab.code=${encodeURIComponent(encodeCode(code))}#shader-lab`);
  await page.locator('section[data-panel="shader-lab"]').scrollIntoViewIfNeeded();
  await expect.poll(() => lab(page, () => window.fresnelLab.panels['shader-lab']?.editor.text())).toBe(code);
  // R = 1 is right past the critical angle only.
  await expect(states(page)).toHaveText(['failed', 'passed', 'failed', 'passed']);
  // Its sphere is a pure mirror: the centre of the left sphere is not the exact one's colour.
  const centres = () => lab(page, () => {
    const c = document.querySelector('section[data-panel="shader-lab"] .sl-spheres canvas');
    const g = c.getContext('2d');
    return [0.25, 0.75].map((x) => [...g.getImageData(Math.round(c.width * x), Math.round(c.height / 2), 1, 1).data]);
  });
  await expect.poll(async () => {
    const [left, right] = await centres();
    return left[3] === 255 && Math.abs(left[0] - right[0]) + Math.abs(left[1] - right[1]) > 30;
  }).toBe(true);
  // Typed: the edit is graded, and the link follows with the code in its compact form.
  const content = page.locator('section[data-panel="shader-lab"] .cm-content');
  await content.click();
  await page.keyboard.press('Control+End');
  await page.keyboard.type('\n// a note');
  await expect.poll(() => lab(page, () => window.fresnelLab.hosts['shader-lab'].values.code)).toBe(`${code}\n// a note`);
  await expect.poll(() => new URL(page.url()).searchParams.get('shader-lab.code')).toBe(encodeCode(`${code}\n// a note`));
  expect(encodeCode(code).length).toBeLessThan(encodeURIComponent(code).length);
  await page.goto(page.url());
  await labReady(page);
  await page.locator('section[data-panel="shader-lab"]').scrollIntoViewIfNeeded();
  await expect.poll(() => lab(page, () => window.fresnelLab.panels['shader-lab']?.editor.text())).toBe(`${code}\n// a note`);
});

test('a lost graphics context is said, and grading comes back with it; the code is kept in the browser', async ({ page }) => {
  await openLab(page, embed('&exercise=safe'));
  await page.getByRole('button', { name: 'Show a reference answer' }).click();
  await expect(states(page)).toHaveText(['passed', 'passed']);
  await lab(page, () => {
    window.lose = window.fresnelLab.panels['shader-lab'].gl.getExtension('WEBGL_lose_context');
    window.lose.loseContext();
  });
  await expect(page.locator('.sl-summary')).toHaveText('The graphics context was lost; grading resumes when it is back.');
  await lab(page, () => window.lose.restoreContext());
  await expect(states(page)).toHaveText(['passed', 'passed']);
  await expect(page.locator('.sl-summary')).toHaveText(/^2 of 2 criteria pass\./);
  // Graded by the student (not only shown), the code is kept: the same exercise opened again
  // without code in the link comes back with it.
  await page.getByRole('button', { name: /^Grade/ }).click();
  await openLab(page, embed('&exercise=safe'));
  await expect.poll(() => lab(page, () => window.fresnelLab.hosts['shader-lab'].values.code)).toContain('total internal reflection');
  await expect(states(page)).toHaveText(['passed', 'passed']);
});

test('homework mode hides the reference answers', async ({ page }) => {
  await openLab(page, embed('&homework=true'));
  await expect(page.getByRole('button', { name: 'Show a reference answer' })).toBeHidden();
  await expect(page.getByRole('button', { name: 'Start over' })).toBeVisible();
  await expect(page.getByRole('textbox', { name: 'GLSL code of the Fresnel function' })).toBeVisible();
});

test.describe('a GPU that refuses the lab\'s own shaders', () => {
  test.use({ allowedErrors: /did not compile|injected refusal/ });
  test('says so, and blames no line of the student\'s code', async ({ page }) => {
    await page.addInitScript(() => {
      const proto = WebGL2RenderingContext.prototype;
      const parameter = proto.getShaderParameter;
      proto.getShaderParameter = function (shader, name) {
        return name === this.COMPILE_STATUS ? false : parameter.call(this, shader, name);
      };
      proto.getShaderInfoLog = () => "ERROR: 0:1: 'injected refusal' : this driver refuses the shader";
    });
    await openLab(page, embed('&exercise=safe'));
    await expect(page.locator('.sl-summary')).toHaveText('This GPU could not compile the lab’s own shaders, so nothing can be graded here: '
      + "ERROR: 0:1: 'injected refusal' : this driver refuses the shader.");
    await expect(page.locator('.sl-errors li')).toHaveCount(0);
    await expect(states(page)).toHaveText(['not graded', 'not graded']);
    await expect(page.locator('.panel-description')).toContainText('could not compile the lab’s own shaders');
  });
});

test('typing over a selection, within a line or across lines, keeps to the page\'s style policy', async ({ page }) => {
  // Left to the browser, typing over highlighted text makes Chrome write style attributes into the merged
  // lines, which the page's Content-Security-Policy refuses (a console error, and the fixture fails).
  await openLab(page, embed());
  const editor = page.locator('.cm-content');
  const text = () => page.evaluate(() => window.fresnelLab.panels['shader-lab'].editor.text());
  await editor.focus();
  await page.keyboard.press('Control+a');
  await page.keyboard.type('float x = 1.0;');
  await expect.poll(text).toBe('float x = 1.0;');
  await page.keyboard.press('Home');
  await page.keyboard.press('Shift+End');
  await page.keyboard.type('9');
  await expect.poll(text).toBe('9');
  await page.evaluate(() => window.fresnelLab.panels['shader-lab'].editor.setText('float a;\nfloat b;\nfloat c;'));
  await page.keyboard.press('Control+a');
  await page.keyboard.press('5');
  await expect.poll(text).toBe('5');
});
