// The lecture composer, from the keys alone: a panel added twice, a text and a question, the list
// reordered with Alt+↑ and the Move buttons (the focus stays on what moved, and each move is said),
// a start state pasted with a key the panel refuses named, and the lecture's link, which must give
// back exactly the lecture composed (inflated here, apart from the lab's code) and,
// where the lecture page reads ?lecture=, open it there with its items in order. Then what comes
// from outside: a damaged link and a file that is no lecture are refused in words on a working page.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { strFromU8, unzipSync } from 'fflate';
import { test, expect, labReady } from './fixtures.js';
import { seriousViolations } from './audit.js';
import { deflateRawSync, inflateRawSync } from 'node:zlib';

/** A lecture link's lecture, read apart from the lab: L1. + base64url of the raw DEFLATE of its JSON. */
function lectureOf(link) {
  const code = new URL(link).searchParams.get('lecture');
  expect(code.startsWith('L1.')).toBe(true);
  return JSON.parse(inflateRawSync(Buffer.from(code.slice(3), 'base64url')).toString('utf8'));
}

/** Presses Tab until the focused element matches `selector` (at most `limit` presses). */
async function tabTo(page, selector, limit = 200) {
  for (let i = 0; i < limit; i += 1) {
    if (await page.evaluate((s) => document.activeElement?.matches(s) ?? false, selector)) return;
    await page.keyboard.press('Tab');
  }
  throw new Error(`Tab never reached ${selector}`);
}
const focusedKey = (page) => page.evaluate(() => document.activeElement?.closest('.cp-item')?.getAttribute('data-key') ?? null);

async function openEmpty(page) {
  await page.goto('compose.html');
  await page.evaluate(() => localStorage.removeItem('fresnel-lab:composer'));
  await page.reload();
  await expect(page.locator('.cp-empty')).toBeVisible();
}

test('a lecture composed by keyboard alone gives a link that holds it, in order', async ({ page }) => {
  test.setTimeout(60_000);
  await openEmpty(page);
  const status = page.locator('.cp-status');

  // The hero twice (Enter, then Space on the same button: the focus stays on Add), then Schlick.
  await page.locator('.cp-catalogue').getByRole('button', { name: 'Add “Exact Fresnel vs Schlick\'s approximation”' }).focus();
  await page.keyboard.press('Enter');
  await page.keyboard.press('Space');
  await expect(status).toHaveText(/as item 2 of 2/);
  await tabTo(page, 'button[data-panel="schlick"]');
  await page.keyboard.press('Enter');
  // A question to the room: the select by its arrow keys, then its Add button.
  await page.getByLabel('A question to the room, from the homework bank').focus();
  await page.keyboard.press('Home');
  await page.keyboard.press('ArrowDown');
  const question = await page.getByLabel('A question to the room, from the homework bank').inputValue();
  // An option shows a prompt's first 110 characters; the whole prompt, with the room's numbers, is below the select.
  await page.getByLabel('A question to the room, from the homework bank').selectOption('exact-r');
  await expect(page.locator('.cp-question-preview')).toHaveText(
    /^Light meets a surface from air at θ = \d+°, into nt = [\d.]+\. What fraction R is reflected \(unpolarised\)\? To 3 decimals\.$/);
  await page.getByLabel('A question to the room, from the homework bank').selectOption(question);
  await page.getByLabel('A question to the room, from the homework bank').focus();
  await page.keyboard.press('Tab');
  await page.keyboard.press('Enter');
  await expect(status).toHaveText(/as item 4 of 4/);
  // The question's card names the panel it is asked on: the one whose group the catalogue lists it in.
  const group = await page.locator('.cp-catalogue select option:checked').evaluate((o) => o.parentElement.label);
  await expect(page.locator('.cp-item').nth(3).locator('p.cp-muted', { hasText: 'On the panel' }))
    .toHaveText(`On the panel “${group}”; the room predicts or answers, then you reveal.`);
  // A text item, written in its own fields.
  await page.getByRole('button', { name: 'Add a text (an agenda, references)' }).focus();
  await page.keyboard.press('Enter');
  await expect(page.locator('.cp-item')).toHaveCount(5);
  const textCard = page.locator('.cp-item').nth(4);
  await textCard.getByLabel('Heading').focus();
  await page.keyboard.type('Agenda');
  await page.keyboard.press('Tab');
  await page.keyboard.type('- Exact against *Schlick*\n- The critical angle, $\\theta_c$');
  await expect(textCard.locator('.cp-preview li')).toHaveCount(2);
  await expect(textCard.locator('.cp-preview em')).toHaveText('Schlick');

  // The text first: Alt+↑ four times from its card, the focus kept on it and each move said.
  const textKey = await textCard.getAttribute('data-key');
  await textCard.focus();
  for (let i = 0; i < 4; i += 1) await page.keyboard.press('Alt+ArrowUp');
  await expect(status).toHaveText('Moved “Agenda” to position 1 of 5.');
  expect(await focusedKey(page)).toBe(textKey);
  await page.keyboard.press('Alt+ArrowUp');
  await expect(status).toHaveText('“Agenda” is already first.');
  // The question up one with its Move up button: the focus stays on that button.
  const questionCard = page.locator('.cp-item-question');
  const questionKey = await questionCard.getAttribute('data-key');
  await questionCard.getByRole('button', { name: 'Move up' }).focus();
  await page.keyboard.press('Enter');
  await expect(status).toHaveText(/to position 4 of 5/);
  expect(await page.evaluate(() => document.activeElement?.textContent)).toBe('Move up');
  expect(await focusedKey(page)).toBe(questionKey);
  expect(await page.locator('.cp-item').evaluateAll((els) => els.map((e) => /cp-item-(\w+)/.exec(e.className)[1])))
    .toEqual(['text', 'panel', 'panel', 'question', 'panel']);

  // The second hero: glass to air from a pasted embed link; the key it does not have is named.
  const second = page.locator('.cp-item').nth(2);
  await second.getByLabel('Heading').focus();
  await page.keyboard.type('Glass to air');
  await second.getByLabel(/Start state: paste a link/).focus();
  await page.keyboard.type('embed.html?panel=spheres&nI=1.5&nT=1&lock=nI&bogus=2');
  await page.keyboard.press('Enter');
  await expect(second.locator('.cp-start-result')).toContainText('Refused: bogus=2 is not a parameter of this panel');
  await expect(second.locator('.cp-start-summary')).toContainText('n');
  await page.getByLabel('Title of the lecture').focus();
  await page.keyboard.press('Control+A');
  await page.keyboard.type('Optics, my way');

  const link = await page.getByLabel('Lecture link').inputValue();
  expect(link).toMatch(/\/index\.html\?lecture=L1\./);
  const lecture = lectureOf(link);
  expect(lecture).toMatchObject({ kind: 'fresnel-lab-lecture', version: 1, title: 'Optics, my way' });
  expect(lecture.items).toEqual([
    { type: 'text', heading: 'Agenda', text: '- Exact against *Schlick*\n- The critical angle, $\\theta_c$' },
    { type: 'panel', panel: 'spheres' },
    { type: 'panel', panel: 'spheres', heading: 'Glass to air', state: { nI: 1.5, nT: 1 }, lock: ['nI'] },
    { type: 'question', question },
    { type: 'panel', panel: 'schlick' },
  ]);
  // Kept in the browser: a reload brings the same lecture back.
  await page.reload();
  await expect(page.getByLabel('Lecture link')).toHaveValue(link);

  // The lecture page: where it reads ?lecture=, the composed items in their order.
  if (readFileSync(new URL('../../src/main.js', import.meta.url), 'utf8').includes('openLecture')) {
    await page.goto(link);
    await expect(page.locator('main')).toContainText('Agenda');
    await expect.poll(() => page.locator('main [data-panel]').evaluateAll((els) => els.map((e) => e.getAttribute('data-panel'))))
      .toEqual(['spheres', 'spheres', 'schlick']);
    await expect(page.locator('main')).toContainText('Glass to air');
  }
});

test('a lecture composed in a language carries it: in its data and its link, and the lecture page opens in it', async ({ page }) => {
  await page.goto('compose.html?lang=en-XA'); // the pseudo-locale: every word of the catalogue ⟦bracketed⟧
  await page.evaluate(() => localStorage.removeItem('fresnel-lab:composer'));
  await page.reload();
  await page.locator('button[data-panel="schlick"]').click();
  const link = await page.locator('.cp-link input').inputValue();
  expect(new URL(link).searchParams.get('lang')).toBe('en-XA');
  expect(lectureOf(link).lang).toBe('en-XA');
  expect(await page.evaluate(() => window.fresnelLab.composer.lecture().lang)).toBe('en-XA');

  await page.goto(link);
  await labReady(page);
  expect(await page.evaluate(() => document.documentElement.lang)).toBe('en-XA');
  await expect(page.locator('.site-title p')).toHaveText(/^⟦.+⟧$/); // the composed lecture's intro
  await expect(page.locator('section[data-panel="schlick"] h2')).toHaveText(/^⟦.+⟧$/);
  await expect(page.locator('section[data-panel="schlick"] .toolbar button').first()).toHaveText(/^⟦.+⟧$/);
});

test('a lecture opens in its own language on the lecture page and in the composer, which keeps it; ?lang= still wins', async ({ page }) => {
  const spanish = JSON.parse(readFileSync(resolve(import.meta.dirname, '../../locales/es.json'), 'utf8'));
  const lecture = { kind: 'fresnel-lab-lecture', version: 1, title: 'Óptica', lang: 'es', items: [{ type: 'panel', panel: 'schlick' }] };
  const code = `L1.${deflateRawSync(Buffer.from(JSON.stringify(lecture))).toString('base64url')}`;
  // A reader whose browser speaks English and who chose English here before: a lecture's language
  // still wins, as a homework sheet's does (docs/student/language.md).
  await page.goto('./');
  await page.evaluate(() => localStorage.setItem('fresnel-lab:language', 'en'));
  await page.goto(`index.html?lecture=${code}`);
  await labReady(page);
  await expect(page.locator('html')).toHaveAttribute('lang', 'es');
  await expect(page.locator('section[data-panel="schlick"] h2')).toHaveText(spanish.panels['schlick.title']);
  // Its Edit link goes on in the page's language, with the lecture.
  const edit = new URL(await page.locator('.compose-offer a').getAttribute('href'), page.url());
  expect(edit.searchParams.get('lang')).toBe('es');
  expect(lectureOf(edit.href).lang).toBe('es');
  // The reader's ?lang= wins, and the Edit link carries it.
  await page.goto(`index.html?lecture=${code}&lang=en`);
  await labReady(page);
  await expect(page.locator('html')).toHaveAttribute('lang', 'en');
  await page.goto(await page.locator('.compose-offer a').getAttribute('href'));
  // The composer in English keeps the lecture Spanish: shown, and written into its link and data.
  await expect(page.locator('html')).toHaveAttribute('lang', 'en');
  await expect(page.getByLabel('Language of the lecture')).toHaveValue('es');
  await page.getByLabel('Title of the lecture').fill('Óptica, segunda parte');
  const link = await page.getByLabel('Lecture link').inputValue();
  expect(new URL(link).searchParams.get('lang')).toBe('es');
  expect(lectureOf(link)).toMatchObject({ title: 'Óptica, segunda parte', lang: 'es' });
  // Changed only by the lecturer's choice.
  await page.getByLabel('Language of the lecture').selectOption('en');
  await expect.poll(async () => lectureOf(await page.getByLabel('Lecture link').inputValue()).lang).toBe('en');
  // Opened for editing without ?lang=, the composer speaks the lecture's language.
  await page.goto(`compose.html?lecture=${code}`);
  await expect(page.locator('html')).toHaveAttribute('lang', 'es');
  await expect(page.getByRole('heading', { level: 1 })).toHaveText(spanish.compose.heading);
  await expect(page.getByLabel(spanish.compose.languageField)).toHaveValue('es');
});

test('a lecture link opens for editing; a damaged link and a file that is no lecture are refused in words', async ({ page }) => {
  const shared = { kind: 'fresnel-lab-lecture', version: 1, title: 'Shared', items: [{ type: 'panel', panel: 'metals' }, { type: 'panel', panel: 'bogus' }] };
  const code = `L1.${deflateRawSync(Buffer.from(JSON.stringify(shared))).toString('base64url')}`;
  await page.goto(`compose.html?lecture=${code}`);
  await expect(page.getByLabel('Title of the lecture')).toHaveValue('Shared');
  await expect(page.locator('.cp-item')).toHaveCount(1);
  await expect(page.locator('.cp-notices')).toContainText('bogus is no panel of the lab');

  await page.goto('compose.html?lecture=L1.not-a-lecture');
  await expect(page.getByRole('alert')).toContainText('This lecture link cannot be opened');
  await page.locator('button[data-panel="metals"]').click();
  await expect(page.locator('.cp-item')).not.toHaveCount(0);
  await page.getByLabel('Open a lecture file').setInputFiles({ name: 'x.json', mimeType: 'application/json', buffer: Buffer.from('{"kind":"fresnel-lab-lecture","version":9}') });
  await expect(page.locator('.cp-message')).toContainText('x.json is not a lecture the lab can open');
  await expect(page.locator('.cp-message')).toContainText('version 9');
  // A lecture file with a panel that does not exist: opened, the panel named, the rest kept.
  const lecture = { kind: 'fresnel-lab-lecture', version: 1, title: 'From a file', items: [{ type: 'panel', panel: 'nope' }, { type: 'text', text: 'Kept' }] };
  await page.getByLabel('Open a lecture file').setInputFiles({ name: 'y.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(lecture)) });
  await expect(page.locator('.cp-notices')).toContainText('nope is no panel of the lab');
  await expect(page.locator('.cp-item')).toHaveCount(1);
  await expect(page.getByLabel('Title of the lecture')).toHaveValue('From a file');
  // Dragged by its handle: the text goes below a panel added after it.
  await page.locator('button[data-panel="schlick"]').click();
  const handle = page.locator('.cp-item').first().locator('.cp-handle');
  const target = await page.locator('.cp-item').nth(1).boundingBox();
  await handle.hover();
  await page.mouse.down();
  await page.mouse.move(target.x + 20, target.y + target.height - 5, { steps: 5 });
  await page.mouse.up();
  await expect(page.locator('.cp-item').first()).toHaveClass(/cp-item-panel/);
  await expect(page.locator('.cp-status')).toHaveText(/Moved “Kept” to position 2 of 2/);
});

test('a panel’s current view taken from its preview, the exports, and the audit in both themes', async ({ page }) => {
  test.setTimeout(60_000);
  await openEmpty(page);
  await page.locator('button[data-panel="schlick"]').click();
  await page.getByRole('button', { name: 'Add a text (an agenda, references)' }).click();
  await page.locator('.cp-item-text').getByLabel('Text', { exact: true }).fill('Read *this*: $R_0$');
  const item = page.locator('.cp-item-panel');
  await item.getByRole('button', { name: 'Show the panel' }).click();
  const take = item.getByRole('button', { name: 'Take the panel’s current view' });
  await expect(take).toBeEnabled(); // the embed said fresnel-lab:ready
  // The view changed inside the panel (here by a message of its own page), then taken.
  const frame = page.frame({ url: /embed\.html\?panel=schlick/ });
  await frame.evaluate(() => window.postMessage({ type: 'fresnel-lab:set', params: { nT: 2.4 } }, '*'));
  await take.click();
  await expect(item.locator('.cp-start-result')).toContainText('Taken from the panel: its current view');
  await expect(item.locator('.cp-start-summary')).toContainText('2.4');
  await expect.poll(async () => lectureOf(await page.getByLabel('Lecture link').inputValue()).items[0]).toEqual({ type: 'panel', panel: 'schlick', state: { nT: 2.4 } });

  // The deck: one file, a slide per item, the panel as this site's embed with its state.
  const [deck] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Download reveal.js deck' }).click()]);
  const deckHtml = readFileSync(await deck.path(), 'utf8');
  expect(deckHtml).toMatch(/<iframe[^>]+embed\.html\?panel=schlick[^"]*nT=2\.4/);
  expect(deckHtml).toContain('Read <em>this</em>');
  // The offline lecture: made from the built single-file pages; the development server has none, and says so.
  const offline = page.getByRole('button', { name: /^Download offline lecture \(\.zip/ });
  if (process.env.FRESNEL_LAB_DEV) {
    await offline.click();
    await expect(page.locator('.cp-message')).toContainText('not the single-file lecture page');
  } else {
    // One download that holds everything the lecture needs: the lecture and the embed page its frames open.
    const [file] = await Promise.all([page.waitForEvent('download'), offline.click()]);
    expect(file.suggestedFilename()).toMatch(/\.zip$/);
    const zip = unzipSync(readFileSync(await file.path()));
    const folder = file.suggestedFilename().replace(/\.zip$/, '');
    expect(Object.keys(zip).sort()).toEqual([`${folder}/`, `${folder}/embed.html`, `${folder}/favicon.svg`, `${folder}/index.html`]);
    expect(strFromU8(zip[`${folder}/index.html`])).toContain('<script type="application/json" id="fresnel-lab-lecture">');
    expect(strFromU8(zip[`${folder}/embed.html`])).toBe(readFileSync(resolve(import.meta.dirname, '../../dist/offline/embed.html'), 'utf8'));
  }

  expect(await seriousViolations(page), 'dark').toEqual([]);
  await page.locator('.page-controls').getByLabel('Theme').selectOption('light');
  await expect(page.locator('html')).toHaveAttribute('data-theme', 'light');
  expect(await seriousViolations(page), 'light').toEqual([]);
});

test('in one column (800 px wide) the catalogue scrolls away above the lecture, and a card’s controls take a click', async ({ page }) => {
  await page.setViewportSize({ width: 800, height: 720 });
  await openEmpty(page);
  for (const panel of ['schlick', 'metals', 'spheres']) await page.locator(`.cp-catalogue button[data-panel="${panel}"]`).click();
  await expect(page.locator('.cp-item')).toHaveCount(3);
  const [catalogue, lecture] = await Promise.all(['.cp-catalogue', '.cp-lecture'].map((s) => page.locator(s).boundingBox()));
  expect(lecture.y, 'one column: the lecture below the catalogue').toBeGreaterThanOrEqual(catalogue.y + catalogue.height);
  // A real click: Playwright clicks only where the button itself is hit, so one under the catalogue fails here.
  const item = page.locator('.cp-item-panel').first();
  const show = item.getByRole('button', { name: 'Show the panel' });
  await expect(show).toBeVisible(); // the card's editor arrives with its module; then a covered button fails fast
  await show.click({ timeout: 5_000 });
  await expect(item.getByRole('button', { name: 'Hide the panel' })).toHaveAttribute('aria-expanded', 'true');
  await expect(item.locator('iframe.cp-frame')).toBeVisible();
  // Nothing of the catalogue lies over the card where the viewport shows it.
  const covered = await item.evaluate((card) => {
    const box = card.getBoundingClientRect();
    const top = Math.max(box.top, 0) + 4;
    return [0.1, 0.5, 0.9].some((f) => document.elementFromPoint(box.left + f * box.width, top)?.closest('.cp-catalogue'));
  });
  expect(covered).toBe(false);
});
