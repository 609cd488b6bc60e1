// The homework page: a lecturer composes a sheet, a student predicts and answers on the panels,
// hands in a file and a code, and the lecturer checks them; lecture mode judges nothing until the
// lecturer reveals; bad sheets and codes are refused in words; and all of it works from the keys.
// The expected answers here are worked out independently of the page (Brewster's tan θ = n_t/n_i,
// the s/p Fresnel equations), from the numbers each student's page prints.
import { readFileSync, writeFileSync } from 'node:fs';
import { test, expect } from './fixtures.js';
import { schema as polarizationSchema } from '../../src/panels/polarization/schema.js';
import { seriousViolations } from './audit.js';

const DEG = Math.PI / 180;
const sheetLink = (sheet) => `homework.html?sheet=${Buffer.from(JSON.stringify(sheet)).toString('base64url')}`;
const SHEET = { version: 1, title: 'Week 3', items: [{ question: 'brewster-predict' }, { question: 'exact-r' }, { question: 'metal-grazing' }] };

/** Unpolarised R from the s and p amplitudes (Hecht, Optics §4.6), written apart from the lab's code. */
function reflectance(thetaDeg, n1, n2) {
  const ci = Math.cos(thetaDeg * DEG);
  const ct = Math.sqrt(1 - ((n1 / n2) * Math.sin(thetaDeg * DEG)) ** 2);
  const rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
  const rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
  return (rs * rs + rp * rp) / 2;
}
const numberAfter = (text, label) => Number(new RegExp(`${label}\\s*=\\s*(\\d+(?:\\.\\d+)?)`).exec(text)[1]);
const card = (page, n) => page.locator(`#question-${n}`);

/** Presses Tab until the focused element matches `selector` (at most `limit` presses). */
async function tabTo(page, selector, limit = 400) {
  for (let i = 0; i < limit; i += 1) {
    if (await page.evaluate((s) => document.activeElement?.matches(s) ?? false, selector)) return;
    await page.keyboard.press('Tab');
  }
  throw new Error(`Tab never reached ${selector}`);
}

test('a student predicts, answers right and wrong, hands in, and the file is checked by recomputation', async ({ page }) => {
  test.setTimeout(180_000);
  await page.goto('homework.html');
  await page.getByLabel('Title').fill('Week 3');
  for (const id of ['brewster-predict', 'exact-r', 'metal-grazing']) await page.locator(`#pick-${id}`).check();
  const link = await page.getByLabel('Link for students').inputValue();
  expect(link).toMatch(/homework\.html\?sheet=/);
  await page.goto(link);

  const seed = await page.locator('.hw-seed').textContent();
  expect(seed).toMatch(/^[a-z2-9]{8}$/);
  // 1. Predict: no panel (which would show the answer) until the prediction is committed.
  const nT = numberAfter(await card(page, 1).locator('.hw-prompt').textContent(), 'n_?t');
  const brewster = Math.atan(nT) / DEG;
  await expect(card(page, 1).locator('iframe')).toHaveCount(0);
  await expect(card(page, 1).locator('.predict-true')).toHaveCount(0);
  // No panel anywhere on the sheet yet: the polarization or exact-formula panel could give it away.
  await expect(card(page, 2).locator('.hw-panel-waiting')).toBeVisible();
  await expect(page.locator('iframe')).toHaveCount(0);
  // Any angle can be committed, the marker's start (45°) included; the button names the one it commits.
  await expect(card(page, 1).getByRole('button', { name: 'Commit prediction: 45.0°' })).toBeEnabled();
  const marker = card(page, 1).getByRole('slider');
  await marker.focus();
  await page.keyboard.press('Home');
  for (let i = 0; i < Math.round(brewster); i += 1) await page.keyboard.press('ArrowRight');
  await expect(marker).toHaveAttribute('aria-valuenow', Math.round(brewster).toFixed(1));
  await card(page, 1).getByRole('button', { name: `Commit prediction: ${Math.round(brewster).toFixed(1)}°` }).click();
  await expect(card(page, 1).locator('.hw-result')).toHaveText(new RegExp(`^Right\\. The computed answer is ${brewster.toFixed(2)}°`));
  await expect(card(page, 1).locator('.predict-true')).toHaveCount(1);
  await expect(card(page, 1).locator('.predict-marker text')).toHaveText(`yours: ${Math.round(brewster).toFixed(1)}°`);
  // As every embed link is written: the panel, then the values that differ from its defaults.
  const nTInLink = nT === polarizationSchema.nT.default ? '' : `&nT=${nT}`;
  await expect(card(page, 1).locator('iframe')).toHaveAttribute('src', new RegExp(`embed\\.html\\?panel=polarization${nTInLink}$`));
  await expect(page.locator('iframe')).toHaveCount(3);
  await expect(card(page, 1).locator('.hw-result')).toBeFocused(); // the keyboard is left at the result, not on <body>

  // 2. Numeric: wrong first (told how far off, to try again), then right, typed as a percentage.
  const prompt = await card(page, 2).locator('.hw-prompt').textContent();
  const R = reflectance(numberAfter(prompt, 'θ'), 1, numberAfter(prompt, 'n_?t'));
  const field = card(page, 2).getByRole('textbox');
  await field.fill((R + 0.01).toFixed(3));
  await field.press('Enter');
  await expect(card(page, 2).locator('.hw-result')).toHaveText(/^Off by 0\.0(09|10)\d*; the tolerance is 0\.0005\. Try again\.$/);
  await field.fill(`${(R * 100).toFixed(2)} %`);
  await card(page, 2).getByRole('button', { name: 'Check' }).click();
  await expect(card(page, 2).locator('.hw-result')).toHaveText(new RegExp(`^Right\\. The computed answer is ${R.toFixed(4)}`));

  // 3. Choice: the misconception, with the panel's explanation under it.
  await card(page, 3).getByRole('radio', { name: /keeps its colour/ }).check();
  await card(page, 3).getByRole('button', { name: 'Check' }).click();
  await expect(card(page, 3).locator('.hw-result')).toHaveText(/^Not this one/);
  await expect(card(page, 3).locator('.hw-chosen .hw-why')).toHaveText(/^No: head-on the channels are/);

  // Kept in the browser: a reload brings every answer back.
  await page.reload();
  await expect(page.locator('.hw-seed')).toHaveText(seed);
  await expect(card(page, 2).getByRole('textbox')).toHaveValue(`${(R * 100).toFixed(2)} %`);
  await expect(card(page, 1).locator('.predict-true')).toHaveCount(1);
  await expect(card(page, 3).getByRole('radio', { name: /keeps its colour/ })).toBeChecked();

  // Hand in: a file and the same as a code; without a name, the page asks first and saves nothing until told to.
  let saved = 0;
  page.on('download', () => { saved += 1; });
  await page.getByLabel(/Your name/).fill('');
  await page.getByRole('button', { name: /^Hand in/ }).click();
  const confirm = page.locator('.hw-confirm');
  await expect(confirm).toBeVisible();
  await expect(confirm).toHaveText(/^Your name is empty, so the lecturer cannot tell whose hand-in this is\. Hand in anyway\?/);
  await expect(confirm.locator('.hw-confirm-text')).toBeFocused();
  expect(await seriousViolations(page), 'audit with the question before handing in').toEqual([]);
  await confirm.getByRole('button', { name: 'Go back' }).click();
  await expect(confirm).toBeHidden();
  await expect(page.getByLabel(/Your name/)).toBeFocused();
  expect(saved).toBe(0);
  await page.getByLabel(/Your name/).fill('Ada');
  const downloading = page.waitForEvent('download');
  await page.getByRole('button', { name: /^Hand in/ }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toBe(`fresnel-lab-week-3-${seed}.json`);
  const file = JSON.parse(readFileSync(await download.path(), 'utf8'));
  expect(file).toMatchObject({ kind: 'fresnel-lab-hand-in', version: 1, seed, name: 'Ada', sheet: { title: 'Week 3' }, attempts: [1, 2, 1] });
  expect(file.answers).toEqual([Math.round(brewster), `${(R * 100).toFixed(2)} %`, 'keeps-colour']);
  await expect(page.locator('.hw-hand-in-status')).toHaveText(/^Handed in at .*: saved as fresnel-lab-week-3-/);
  const code = await page.getByLabel(/Hand-in code/).inputValue();
  expect(code).toMatch(/^FLH1\.[A-Za-z0-9_-]+$/);

  // The lecturer checks the file and the code: 2 of 3, recomputed. A file that says it scored 3,
  // with every answer marked correct, still gets 2.
  await page.goto('homework.html');
  await page.getByLabel('The sheet you set').fill(link);
  const forged = test.info().outputPath('forged.json');
  writeFileSync(forged, JSON.stringify({ ...file, score: 3, total: 3, answers: file.answers.map((a) => ({ value: a, correct: true })) }));
  const edited = test.info().outputPath('edited.json'); // the hard question dropped from the sheet
  writeFileSync(edited, JSON.stringify({ ...file, sheet: { ...file.sheet, items: file.sheet.items.slice(0, 2) }, answers: file.answers.slice(0, 2) }));
  await page.getByLabel('Or choose handed-in files').setInputFiles([await download.path(), forged, edited]);
  await expect(page.locator('.hw-score')).toHaveCount(2);
  for (const score of await page.locator('.hw-score').all()) await expect(score).toHaveText(new RegExp(`^Week 3: Ada, seed ${seed}, handed in .*Score 2 of 3, recomputed\\.$`));
  await expect(page.locator('.hw-report').nth(2).getByRole('alert')).toContainText('it answers another sheet');
  await page.getByLabel(/Paste a hand-in code/).fill(code);
  await page.getByRole('button', { name: 'Check the code' }).click();
  await expect(page.locator('.hw-score')).toHaveText(/Score 2 of 3, recomputed/);
  const rows = page.locator('.hw-report-table tbody tr');
  await expect(rows.nth(0).locator('td').nth(4)).toHaveText(/^right: /);
  await expect(rows.nth(1).locator('td').nth(5)).toHaveText('2'); // tries
  await expect(rows.nth(2).locator('td').nth(4)).toHaveText(/^wrong: No:/);
  await expect(rows.nth(2).locator('td').nth(3)).toHaveText(/Nearly white/);
});

test('the marker\'s start is a prediction too: 45° is committed as it stands', async ({ page }) => {
  await page.goto(`${sheetLink({ ...SHEET, seed: 'start' })}`);
  await card(page, 1).getByRole('button', { name: 'Commit prediction: 45.0°' }).click();
  await expect(card(page, 1).locator('.predict-marker text')).toHaveText('yours: 45.0°');
  await expect(card(page, 1).locator('.hw-result')).toHaveText(/The computed answer is \d+\.\d\d°/);
});

test('lecture mode judges nothing until the lecturer reveals, one question or all', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto(`${sheetLink({ ...SHEET, reveal: 'lecturer', seed: 'class' })}`);
  await expect(page.locator('.hw-meta')).toContainText('the same for everyone');
  await expect(page.getByLabel(/Lecture mode/)).toBeChecked();
  await card(page, 1).getByRole('slider').press('ArrowRight');
  await card(page, 1).getByRole('button', { name: 'Commit prediction' }).click();
  await expect(card(page, 1).locator('.hw-result')).toHaveText(/^Answer saved\. The answer is shown when the lecturer reveals it\.$/);
  await expect(card(page, 1).locator('.predict-true')).toHaveCount(0);
  await expect(card(page, 1).locator('iframe')).toHaveCount(0);
  await card(page, 2).getByRole('textbox').fill('0.5');
  await card(page, 2).getByRole('textbox').press('Enter');
  await expect(card(page, 2).locator('.hw-result')).toHaveText(/^Answer saved/);

  await card(page, 1).getByRole('button', { name: 'Reveal the answer' }).click();
  await expect(card(page, 1).locator('.predict-true')).toHaveCount(1);
  await expect(card(page, 1).locator('.hw-result')).toHaveText(/computed answer is \d+\.\d\d°/);
  await expect(card(page, 1).locator('iframe')).toHaveCount(1);
  await expect(card(page, 2).locator('.hw-result')).toHaveText(/^Answer saved/); // the others still wait
  await expect(card(page, 1).getByRole('slider')).toHaveAttribute('aria-disabled', 'true');
  await page.getByRole('button', { name: 'Reveal every answer' }).click();
  await expect(card(page, 2).getByRole('textbox')).toBeDisabled(); // revealed: no more answers
  await expect(card(page, 2).locator('.hw-result')).toHaveText(/^Not within the tolerance: yours 0\.5000\. The computed answer is 0\.\d{4} \(checked within 0\.0005\)\.$/);
  await expect(card(page, 3).locator('.hw-result')).toHaveText(/^The answer: “Nearly white/);
  await expect(card(page, 3).locator('.hw-true')).toHaveCount(1);
  await expect(card(page, 3).locator('.hw-why')).toHaveText([/^No:/, /^Right:/, /^No:/]);
});

test('a prediction revealed before it is committed shows no "yours"; lecture mode switched on hides what was judged', async ({ page }) => {
  await page.goto(`${sheetLink({ ...SHEET, reveal: 'lecturer' })}&seed=late`);
  await card(page, 1).getByRole('button', { name: 'Reveal the answer' }).click();
  await expect(card(page, 1).locator('.hw-result')).toHaveText(/^No prediction was committed\. The computed answer is \d+\.\d\d°/);
  await expect(card(page, 1).locator('.predict-marker')).toBeHidden();
  await expect(card(page, 1).locator('.predict-caption')).toHaveText(/^Rₚ against θ; the true angle is \d+\.\d\d°\.$/);
  await expect(card(page, 1).getByRole('button', { name: 'Commit prediction' })).toBeDisabled();
  // Lecture mode off, then an answer judged at once; on again, and the judgement is hidden.
  await page.getByLabel(/Lecture mode/).uncheck();
  await expect(card(page, 1).locator('.predict-true')).toHaveCount(1); // what was revealed stays revealed
  await card(page, 3).getByRole('radio', { name: /keeps its colour/ }).check();
  await card(page, 3).getByRole('button', { name: 'Check' }).click();
  await expect(card(page, 3).locator('.hw-chosen .hw-why')).toHaveText(/^No:/);
  await page.getByLabel(/Lecture mode/).check();
  await expect(card(page, 3).locator('.hw-result')).toHaveText(/^Answer saved/);
  await expect(card(page, 3).locator('.hw-why:not(:empty)')).toHaveCount(0);
  await expect(card(page, 3).locator('.hw-chosen')).toHaveCount(0);
});

test('bad sheets, links and codes are refused with their reasons, and the page still works', async ({ page }) => {
  await page.goto('homework.html?sheet=not-a-sheet!');
  await expect(page.getByRole('alert')).toContainText('This sheet link cannot be used');
  await expect(page.getByRole('alert')).toContainText('damaged');
  await expect(page.getByRole('heading', { name: 'Compose a sheet' })).toBeVisible();
  await page.goto(sheetLink({ version: 1, title: 'x', items: [{ question: 'no-such-question' }, { question: 'exact-r', state: { 'bad key': 1 } }] }));
  await expect(page.getByRole('alert')).toContainText('item 1: there is no question “no-such-question”');
  await expect(page.getByRole('alert')).toContainText('item 2: “bad key” is not a panel value');
  await page.goto(sheetLink({ version: 1, title: 'x', items: [{ question: 'exact-r', state: { panel: 'schlick' } }] }));
  await expect(page.getByRole('alert')).toContainText('item 1: panel is not a panel value (it is an option of the embed page)');
  for (const [text, reason] of [['FLH1.@@@', 'damaged'], ['hello', 'neither a handed-in file'], ['{"kind": 1', 'not readable JSON'],
    [`FLH1.${Buffer.from(JSON.stringify({ version: 1, sheet: SHEET, seed: 'a', answers: [] })).toString('base64url')}`, 'one entry per question']]) {
    await page.getByLabel(/Paste a hand-in code/).fill(text);
    await page.getByRole('button', { name: 'Check the code' }).click();
    await expect(page.locator('.hw-report [role="alert"]'), text).toContainText(reason);
  }
  // The composer offers nothing until the sheet is one a student's page accepts.
  await expect(page.getByText('Pick at least one question.')).toBeVisible();
  await expect(page.getByRole('button', { name: 'Copy the link' })).toBeDisabled();
  await page.locator('#pick-exact-r').check();
  const state = page.locator('.hw-pick', { has: page.locator('#pick-exact-r') }).getByRole('textbox', { name: 'Start state (optional)' });
  await state.fill('embed.html?panel=schlick&theta=10');
  await expect(page.getByText('Question 1 (Reflection math: the exact formula): This link is for “Schlick\'s approximation”, not “Reflection math: the exact formula”.')).toBeVisible();
  await state.fill('embed.html?panel=exact-fresnel&theta=10&theme=light');
  const link = await page.getByLabel('Link for students').inputValue();
  await page.goto(link);
  // The question's own n_t wins over the start state; a link leaves out a value at its default
  // (1.5, which the seed draws one time in seven), so the expected link follows the prompt's n_t.
  const nT = (await card(page, 1).locator('.hw-prompt').textContent())?.match(/n_?t = (\d+(?:\.\d+)?)/)?.[1];
  expect(nT).toBeTruthy();
  const expected = `embed.html?panel=exact-fresnel&theta=10${nT === '1.5' ? '' : `&nT=${nT}`}`;
  await expect(card(page, 1).locator('iframe')).toHaveAttribute('src', new RegExp(`${expected.replace(/[.?]/g, '\\$&')}$`));
});

test('a sheet opens in the language it was made in; the reader\'s ?lang= still wins', async ({ page }) => {
  // Made on a page in the pseudo-locale (every catalogue message bracketed ⟦…⟧), as a sheet made in Spanish is.
  await page.goto('homework.html?lang=en-XA');
  await expect(page.locator('html')).toHaveAttribute('lang', 'en-XA');
  await page.locator('#pick-exact-r').check();
  const link = await page.locator('.hw-composer-out input[type="text"]').inputValue();
  const code = new URL(link).searchParams.get('sheet');
  expect(JSON.parse(Buffer.from(code, 'base64url').toString('utf8')).lang).toBe('en-XA');
  // Opened without ?lang= (a student's browser, its own language English): the sheet's language.
  await page.goto(`homework.html?sheet=${code}`);
  await expect(page.locator('html')).toHaveAttribute('lang', 'en-XA');
  await expect(card(page, 1).locator('.hw-number')).toHaveText(/^⟦Q/);
  await expect(card(page, 1).locator('.hw-prompt')).toHaveText(/^⟦/);
  await expect(page.locator('.hw-meta').first()).toHaveText(/^⟦.*⟧$/);
  await expect(page.locator('.hw-meta .hw-seed')).toHaveCount(1); // the seed stays in its own element inside the sentence
  // The reader's ?lang= wins over the sheet's.
  await page.goto(`homework.html?sheet=${code}&lang=en`);
  await expect(page.locator('html')).toHaveAttribute('lang', 'en');
  await expect(card(page, 1).locator('.hw-number')).toHaveText('Question 1');
  // A sheet made in English carries English, and one made before sheets carried a language opens in the reader's.
  await page.goto('homework.html');
  await page.locator('#pick-exact-r').check();
  const english = new URL(await page.getByLabel('Link for students').inputValue()).searchParams.get('sheet');
  expect(JSON.parse(Buffer.from(english, 'base64url').toString('utf8')).lang).toBe('en');
  await page.goto(sheetLink(SHEET));
  await expect(card(page, 1).locator('.hw-number')).toHaveText('Question 1');
});

test('keyboard only: compose, predict, answer and check', async ({ page }) => {
  test.setTimeout(180_000);
  await page.goto('homework.html');
  await page.getByLabel('Title').focus();
  await tabTo(page, '#pick-critical-predict');
  await page.keyboard.press('Space');
  await tabTo(page, '#pick-schlick-inside');
  await page.keyboard.press('Space');
  const link = await page.getByLabel('Link for students').inputValue();
  await page.goto(`${link}&seed=keys`);
  const nI = numberAfter(await card(page, 1).locator('.hw-prompt').textContent(), 'n_?i');
  const critical = Math.asin(1 / nI) / DEG;
  await tabTo(page, '[role="slider"]');
  await page.keyboard.press('End');
  for (let i = 0; i < 9; i += 1) await page.keyboard.press('PageDown'); // 90° − 90° = 0°
  for (let i = 0; i < Math.floor(critical); i += 1) await page.keyboard.press('ArrowUp');
  await page.keyboard.down('Shift');
  for (let i = 0; i < Math.round((critical % 1) * 10); i += 1) await page.keyboard.press('ArrowRight');
  await page.keyboard.up('Shift');
  await expect(page.getByRole('slider')).toHaveAttribute('aria-valuetext', `${(Math.round(critical * 10) / 10).toFixed(1)} degrees`);
  await page.keyboard.press('Tab');
  await page.keyboard.press('Enter');
  await expect(card(page, 1).locator('.hw-result')).toHaveText(/^Right\./);
  // The choice: arrows move within the options, Space checks the answer with the focused button.
  await tabTo(page, '#question-2 input[type="radio"]');
  await page.keyboard.press('ArrowDown');
  await expect(card(page, 2).getByRole('radio', { name: /misses total internal reflection/ })).toBeChecked();
  await page.keyboard.press('Tab');
  await page.keyboard.press('Space');
  await expect(card(page, 2).locator('.hw-result')).toHaveText('Right.');
  await expect(card(page, 2).locator('.hw-why')).toHaveText([/^No:/, /^Right:/]);
});

test('markup in a sheet\'s title, a start state, a student\'s name and a file name stays text everywhere', async ({ page }) => {
  test.setTimeout(120_000);
  const { XSS, injected } = await import('./doorFuzz.js');
  const title = `Week 3 ${XSS[0]}`;
  const sheet = { version: 1, title, items: [{ question: 'exact-r', state: { theta: XSS[1].slice(0, 64) } }] };
  await page.goto(sheetLink(sheet));
  await expect(page.locator('h1')).toHaveText(title);
  const name = XSS[4];
  await page.getByLabel(/Your name/).fill(name);
  const frame = () => page.frames().find((f) => f.url().includes('embed.html'));
  await expect.poll(() => Boolean(frame())).toBe(true);
  await frame().waitForFunction(() => window.fresnelLab?.hosts && Object.values(window.fresnelLab.hosts).every((h) => h.mounted));
  await expect(frame().locator('.notice')).toContainText('theta=<svg onload'); // the bad start value quoted as text
  for (const f of page.frames()) expect(await injected(f), f.url()).toEqual([]);

  const downloading = page.waitForEvent('download');
  await page.getByRole('button', { name: /^Hand in/ }).click();
  await expect(page.locator('.hw-confirm')).toHaveText(/^You have not answered the question\. Hand in anyway\?/); // asked first
  await page.getByRole('button', { name: 'Hand in anyway' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).not.toMatch(/[<>"']/);
  const file = JSON.parse(readFileSync(await download.path(), 'utf8'));
  expect(file.name).toBe(name);
  const named = test.info().outputPath(`${XSS[5].replace(/\//g, '')}.json`);
  writeFileSync(named, JSON.stringify(file));
  const notAHandIn = test.info().outputPath(`${XSS[0].replace(/\//g, '')}.txt`);
  writeFileSync(notAHandIn, XSS.join('\n'));
  await page.goto('homework.html');
  await page.getByLabel('The sheet you set').fill(`homework.html?sheet=${Buffer.from(JSON.stringify(sheet)).toString('base64url')}`);
  await page.getByLabel('Or choose handed-in files').setInputFiles([named, notAHandIn]);
  await expect(page.locator('.hw-score')).toHaveCount(1);
  await expect(page.locator('.hw-score')).toContainText(`${title}: ${name}`);
  await expect(page.locator('.hw-report').nth(1)).toContainText('<img src=x'); // the refused file, named as it is
  expect(await injected(page)).toEqual([]);
});
