// The SCORM 1.2 package: made in the composer, unpacked, and run inside an LMS page that provides
// the run-time API (window.API). First a stand-in that records every call and keeps no
// interactions; then scorm-again's Scorm12API, a run-time that checks the data model as an LMS
// does and sets an error code for every call it refuses. The sheet takes the learner's id as its
// seed, keeps answers in cmi.suspend_data (and gets them back from it, on another computer too),
// records each checked answer as an interaction, and at hand-in reports the recomputed score.
import { readFileSync } from 'node:fs';
import { strFromU8, strToU8, unzipSync } from 'fflate';
import { test, expect } from './fixtures.js';
import { hashSeed } from '../../src/homework/seededRandom.js';
import { QUESTIONS } from '../../src/homework/questions.js';
import { questionParams, trueOption } from '../../src/homework/gradeAnswer.js';
import { decimalsFor } from '../../src/homework/formatAnswer.js';
import { interactionProblems } from '../unit/scorm12Formats.js';
import spanish from '../../locales/es.json' with { type: 'json' };

const LMS = `<!doctype html><html><head><meta charset="utf-8"><title>LMS</title><script>
  const data = { 'cmi.core.student_id': 's123', 'cmi.core.student_name': 'Lovelace, Ada', 'cmi.core.lesson_status': 'not attempted',
    'cmi.suspend_data': new URLSearchParams(location.search).get('resume') ?? '' };
  window.calls = [];
  const log = (name, ...args) => { window.calls.push([name, ...args]); return 'true'; };
  window.API = {
    LMSInitialize: (x) => log('LMSInitialize', x), LMSFinish: (x) => log('LMSFinish', x), LMSCommit: (x) => log('LMSCommit', x),
    LMSGetValue: (k) => { log('LMSGetValue', k); return data[k] ?? ''; },
    LMSSetValue: (k, v) => { log('LMSSetValue', k, v); data[k] = v; return 'true'; },
    LMSGetLastError: () => '0', LMSGetErrorString: () => '', LMSGetDiagnostic: () => '',
  };
  window.lmsData = data;
</script></head><body><iframe id="sco" src="homework.html" style="width:1200px;height:900px"></iframe></body></html>`;

/**
 * An LMS page on scorm-again's SCORM 1.2 run-time, started from `stored` (the LMS's cmi data for
 * this learner, as scorm-again's loadFromJSON takes it). window.calls gets every call the package
 * makes, with LMSGetLastError read after it.
 */
const againLms = (stored) => `<!doctype html><html><head><meta charset="utf-8"><title>LMS</title>
<script src="scorm12.js"></script><script>
  const api = new Scorm12API({ logLevel: 5, autocommit: false });
  api.loadFromJSON(${JSON.stringify(stored)});
  window.calls = [];
  const logged = (name) => (...args) => {
    const result = String(api[name](...args));
    window.calls.push({ name, args, result, error: String(api.LMSGetLastError()) });
    return result;
  };
  window.API = {
    ...Object.fromEntries(['LMSInitialize', 'LMSFinish', 'LMSGetValue', 'LMSSetValue', 'LMSCommit'].map((name) => [name, logged(name)])),
    LMSGetLastError: () => api.LMSGetLastError(), LMSGetErrorString: (c) => api.LMSGetErrorString(c), LMSGetDiagnostic: (c) => api.LMSGetDiagnostic(c),
  };
  window.lms = api;
</script></head><body><iframe id="sco" src="homework.html" style="width:1200px;height:900px"></iframe></body></html>`;

const SCORM_AGAIN = readFileSync(new URL('../../node_modules/scorm-again/dist/scorm12.js', import.meta.url));
const SEED = `lms-${hashSeed('s123').toString(36)}`; // the learner's id, hashed

/** The package the composer saves for these questions: its files by name. */
async function composePackage(page, title, picks) {
  await page.goto('homework.html');
  await page.getByLabel('Title').fill(title);
  for (const id of picks) await page.locator(`#pick-${id}`).check();
  const downloading = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Save for an LMS (SCORM 1.2 zip)' }).click();
  const download = await downloading;
  return { name: download.suggestedFilename(), files: unzipSync(new Uint8Array(readFileSync(await download.path()))) };
}

/** Serves the package as an LMS serves it, under its own folder, with `player()` (the LMS page) above it. */
async function serveLms(page, files, player, extra = {}) {
  await page.route('**/lms/**', (route) => {
    const name = new URL(route.request().url()).pathname.split('/lms/')[1];
    if (name === 'player.html') return route.fulfill({ contentType: 'text/html', body: player() });
    if (extra[name]) return route.fulfill(extra[name]);
    const file = files[name];
    return file ? route.fulfill({ contentType: name.endsWith('.svg') ? 'image/svg+xml' : 'text/html', body: Buffer.from(file) }) : route.fulfill({ status: 404 });
  });
}

test('a sheet saved for an LMS reports the recomputed score through the SCORM 1.2 API', async ({ page }) => {
  test.setTimeout(120_000);
  const { name, files } = await composePackage(page, 'Week 3 & more', ['exact-r', 'metal-grazing']);
  expect(name).toBe('fresnel-lab-week-3-more-scorm12.zip');
  expect(Object.keys(files).sort()).toEqual(['embed.html', 'favicon.svg', 'homework.html', 'imsmanifest.xml']);
  const manifest = strFromU8(files['imsmanifest.xml']);
  expect(manifest).toContain('<schemaversion>1.2</schemaversion>');
  expect(manifest).toContain('adlcp:scormtype="sco" href="homework.html"');
  expect(manifest).toContain('<title>Week 3 &amp; more</title>');

  await serveLms(page, files, () => LMS);
  await page.goto('lms/player.html');
  const sco = page.frameLocator('#sco');
  await expect(sco.locator('.hw-seed')).toHaveText(SEED);
  await expect(sco.getByLabel(/Lecture mode/)).toBeHidden(); // in a course, no switch that reveals answers
  await expect(sco.getByLabel(/Your name/)).toHaveValue('Lovelace, Ada');
  await expect(sco.getByText('handing in sends your score to its gradebook')).toBeVisible();
  await sco.locator('#question-2').getByRole('radio', { name: /Nearly white/ }).check();
  await sco.locator('#question-2').getByRole('button', { name: 'Check' }).click();
  await expect(sco.locator('#question-2 .hw-result')).toHaveText('Right.');
  const suspend = await page.evaluate(() => window.lmsData['cmi.suspend_data']);
  expect(JSON.parse(suspend)).toEqual({ seed: SEED, answers: [null, 'towards-white'] });
  await sco.getByRole('button', { name: /^Hand in/ }).click();
  await expect(sco.locator('.hw-hand-in-status')).toContainText('Your score, 1 of 2, went to the course\'s gradebook.');
  const data = await page.evaluate(() => window.lmsData);
  expect(data).toMatchObject({ 'cmi.core.score.raw': '50', 'cmi.core.score.min': '0', 'cmi.core.score.max': '100', 'cmi.core.lesson_status': 'completed' });
  const calls = await page.evaluate(() => window.calls);
  expect(calls[0][0]).toBe('LMSInitialize');
  // This LMS lists no interaction elements and has no count: the page writes none, and works on.
  expect(calls.filter(([n, key]) => n === 'LMSSetValue' && key.startsWith('cmi.interactions.'))).toEqual([]);
  // Leaving the page ends the session: its time, no suspend (it was handed in), LMSFinish last.
  await page.evaluate(() => document.getElementById('sco').remove());
  await expect.poll(() => page.evaluate(() => window.calls.at(-1)?.[0])).toBe('LMSFinish');
  const after = await page.evaluate(() => window.lmsData);
  expect(after['cmi.core.session_time']).toMatch(/^\d{4}:\d\d:\d\d\.\d\d$/);
  expect(after['cmi.core.exit']).toBe('');

  // Another computer: the answers come back from the LMS, not from this browser's storage.
  await page.evaluate(() => localStorage.clear());
  await page.goto(`lms/player.html?resume=${encodeURIComponent(suspend)}`);
  await expect(page.frameLocator('#sco').locator('#question-2').getByRole('radio', { name: /Nearly white/ })).toBeChecked();
  await expect(page.frameLocator('#sco').locator('#question-2 .hw-result')).toHaveText('Right.');
  await expect(page.frameLocator('#sco').locator('.hw-resume-notice')).toHaveCount(0);
  // A copy cut short is refused with a sentence, and the question is open again.
  await page.evaluate(() => localStorage.clear());
  await page.goto(`lms/player.html?resume=${encodeURIComponent(suspend.slice(0, 25))}`);
  await expect(page.frameLocator('#sco').locator('.hw-resume-notice')).toHaveText(/^Your course’s copy of your answers cannot be read \(cut short or changed\)/);
  await expect(page.frameLocator('#sco').locator('#question-2').getByRole('radio', { name: /Nearly white/ })).not.toBeChecked();
});

test('a package opens in the language its sheet was made in', async ({ page }) => {
  test.setTimeout(120_000);
  const { files } = await composePackage(page, 'Week 3', ['exact-r']);
  const inPage = strFromU8(files['homework.html']);
  // The last such block: the page's own script, inlined before it, writes the same tag around a variable.
  const code = [...inPage.matchAll(/id="fresnel-lab-sheet" data-scorm="1">([^<]*)</g)].at(-1)[1];
  const sheet = JSON.parse(Buffer.from(code, 'base64url').toString('utf8'));
  expect(sheet.lang).toBe('en'); // composed on an English page
  // The same package had it been made on a page in Spanish (the single-file page carries every listed language).
  const made = Buffer.from(JSON.stringify({ ...sheet, lang: 'es' })).toString('base64url');
  const at = inPage.lastIndexOf(code);
  await serveLms(page, { ...files, 'homework.html': strToU8(inPage.slice(0, at) + made + inPage.slice(at + code.length)) }, () => LMS);
  await page.goto('lms/player.html');
  const sco = page.frameLocator('#sco');
  await expect(sco.locator('html')).toHaveAttribute('lang', 'es');
  await expect(sco.locator('#question-1 .hw-number')).toHaveText(`${spanish.homework['card.number'].replace('{number}', '1')}`);
});

/** What to answer to question `n` (1-based) of the sheet, and the interaction that check should make. */
function plan(question, n) {
  const params = questionParams(question, SEED);
  const right = n % 2 === 0; // every other question right, the rest wrong
  if (question.kind === 'choice') {
    const options = question.options(params);
    const holds = trueOption(question, params).id;
    return { answer: right ? holds : options.find((o) => o.id !== holds).id, type: 'choice', result: right ? 'correct' : 'wrong' };
  }
  const expected = question.expected(params);
  if (question.kind === 'predict') {
    const near = Math.round(expected); // within the prediction's tolerance (2° or more)
    return { answer: right ? near : Math.max(0, near - 25), type: 'numeric', result: right ? 'correct' : 'wrong' };
  }
  const typed = (right ? expected : expected + 20 * question.tolerance).toFixed(decimalsFor(question));
  return { answer: typed, type: 'numeric', result: right ? 'correct' : 'wrong' };
}

/** Answers one card as a learner does, and waits for the page to judge it right or not. */
async function answer(card, question, value, right) {
  if (question.kind === 'choice') {
    await card.locator(`input[type=radio][value="${value}"]`).check();
    await card.getByRole('button', { name: 'Check' }).click();
  } else if (question.kind === 'predict') {
    const marker = card.getByRole('slider');
    await marker.press('Home');
    for (let i = 0; i < Math.floor(value / 10); i += 1) await marker.press('PageUp');
    for (let i = 0; i < value % 10; i += 1) await marker.press('ArrowRight');
    await expect(marker).toHaveAttribute('aria-valuenow', value.toFixed(1));
    await card.getByRole('button', { name: 'Commit prediction' }).click();
  } else {
    await card.getByRole('textbox').fill(value);
    await card.getByRole('button', { name: 'Check' }).click();
  }
  await expect(card.locator('.hw-result')).toHaveClass(right ? /\bhw-right\b/ : /\bhw-wrong\b/);
}

/** The interactions scorm-again keeps, each as its elements under cmi.interactions.n. */
const interactionsOf = (cmi) => Object.values(cmi.interactions ?? {}).map(({ id, type, student_response, result, time, correct_responses }) => ({
  id, type, student_response, result, time, 'correct_responses.0.pattern': correct_responses?.[0]?.pattern,
}));

test('under scorm-again\'s SCORM 1.2 run-time, 40 questions are answered, reported question by question, handed in and resumed elsewhere without one error', async ({ page }) => {
  test.setTimeout(240_000);
  const { files } = await composePackage(page, 'Forty', ['exact-r']);
  // The composer picks each question of the bank (24) once; a sheet may hold 40 with repeats
  // (readSheet), so the package's page gets such a sheet written in as buildScormPackage writes one.
  const questions = Array.from({ length: 40 }, (_, i) => QUESTIONS[i % QUESTIONS.length]);
  const sheet = { version: 1, title: 'Forty', reveal: 'after-answer', items: questions.map((q) => ({ question: q.id })) };
  const code = Buffer.from(JSON.stringify(sheet)).toString('base64url'); // a sheet's code (sheetCodes.js)
  const page40 = strFromU8(files['homework.html']).replace(/(<script type="application\/json" id="fresnel-lab-sheet" data-scorm="1">)[^<]*(<\/script>)/, `$1${code}$2`);
  expect(page40).toContain(code);
  files['homework.html'] = new TextEncoder().encode(page40);
  let stored = { core: { student_id: 's123', student_name: 'Lovelace, Ada', entry: 'ab-initio' } };
  // The panels are the lecture's own, tested elsewhere; blank here, so that 40 frames cost SwiftShader nothing.
  await serveLms(page, files, () => againLms(stored), {
    'scorm12.js': { contentType: 'text/javascript', body: SCORM_AGAIN },
    'embed.html': { contentType: 'text/html', body: '<!doctype html><title>panel</title>' },
  });
  await page.goto('lms/player.html');
  const sco = page.frameLocator('#sco');
  await expect(sco.locator('.hw-seed')).toHaveText(SEED);

  const started = Date.now();
  const expected = [];
  const finalAnswers = [];
  const retried = questions.findIndex((q, i) => q.kind === 'numeric' && plan(q, i + 1).result === 'correct') + 1;
  for (const [i, question] of questions.entries()) {
    const n = i + 1;
    const card = sco.locator(`#question-${n}`);
    const { answer: value, type, result } = plan(question, n);
    const id = `q${String(n).padStart(2, '0')}-${question.id}`;
    if (n === retried) { // text that is no number first: fill-in, unanticipated; then checked again
      await answer(card, question, 'about half', false);
      expected.push({ id, type: 'fill-in', result: 'unanticipated' });
    }
    await answer(card, question, value, result === 'correct');
    expected.push({ id, type, result });
    finalAnswers.push(value);
  }
  const answering = Date.now() - started;
  await sco.getByRole('button', { name: /^Hand in/ }).click();
  const right = questions.filter((q, i) => plan(q, i + 1).result === 'correct').length;
  await expect(sco.locator('.hw-hand-in-status')).toContainText(`Your score, ${right} of 40, went to the course's gradebook.`);
  await page.evaluate(() => document.getElementById('sco').remove()); // leaving ends the session
  await expect.poll(() => page.evaluate(() => window.calls.at(-1)?.name)).toBe('LMSFinish');

  const calls = await page.evaluate(() => window.calls);
  await test.info().attach('scorm-again calls.json', { body: JSON.stringify(calls, null, 1), contentType: 'application/json' });
  expect(calls.filter((c) => c.error !== '0'), 'calls that set an error code').toEqual([]);
  expect(calls.filter((c) => c.result === 'false'), 'calls that were refused').toEqual([]);
  const { cmi } = await page.evaluate(() => window.lms.renderCommitCMI(true));
  expect(cmi.core).toMatchObject({ score: { raw: String(Math.round((100 * right) / 40)), min: '0', max: '100' }, lesson_status: 'completed', exit: '' });
  expect(cmi.suspend_data.length).toBeLessThanOrEqual(4096); // SCORM 1.2's CMIString4096; scorm-again takes 64000
  expect(JSON.parse(cmi.suspend_data)).toEqual({ seed: SEED, answers: finalAnswers });
  const interactions = interactionsOf(cmi);
  expect(interactions.map(({ id, type, result }) => ({ id, type, result }))).toEqual(expected);
  for (const record of interactions) expect(interactionProblems(record), JSON.stringify(record)).toEqual([]);
  console.log(`[scorm-again] ${calls.length} calls, every LMSGetLastError 0; suspend_data ${cmi.suspend_data.length} characters for 40 answers; ${interactions.length} interactions; answered in ${answering} ms`);

  // Another computer: a fresh browser storage, the LMS's stored data loaded into a new run-time.
  stored = { ...cmi, core: { ...cmi.core, entry: 'resume' } };
  await page.evaluate(() => localStorage.clear());
  await page.goto('lms/player.html');
  await expect(sco.locator('.hw-seed')).toHaveText(SEED);
  const frame = page.frame({ url: /\/lms\/homework\.html/ });
  expect(await frame.evaluate(() => window.fresnelLab.homework.cards.map((c) => c.answer()))).toEqual(finalAnswers);
  await expect(sco.locator('.hw-resume-notice')).toHaveCount(0);
  await expect(sco.locator('#question-2 .hw-result')).toHaveText(/^Right\./); // answered and judged as before
  // Checked again there: the journal goes on at the next index.
  const again = plan(questions[0], 2); // question 1 was answered wrong; now its right option
  await answer(sco.locator('#question-1'), questions[0], again.answer, true);
  await expect.poll(() => page.evaluate(() => window.lms.renderCommitCMI(true).cmi.interactions[41]?.result)).toBe('correct');
  const resumed = await page.evaluate(() => window.calls);
  expect(resumed.filter((c) => c.error !== '0' || c.result === 'false')).toEqual([]);
  expect(resumed.filter((c) => c.name === 'LMSSetValue' && c.args[0].endsWith('.id')).map((c) => c.args)).toEqual([['cmi.interactions.41.id', `q01-${questions[0].id}`]]);
});
