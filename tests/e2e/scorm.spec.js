// The SCORM 1.2 package: made in the composer, unpacked, and run inside a stand-in LMS page that
// provides the run-time API (window.API) and records every call, as Moodle's or Canvas's player
// does. The sheet takes the learner's id as its seed, keeps answers in cmi.suspend_data (and gets
// them back from it), and at hand-in reports the recomputed score.
import { readFileSync } from 'node:fs';
import { strFromU8, unzipSync } from 'fflate';
import { test, expect } from './fixtures.js';
import { hashSeed } from '../../src/homework/seededRandom.js';

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

test('a sheet saved for an LMS reports the recomputed score through the SCORM 1.2 API', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto('homework.html');
  await page.getByLabel('Title').fill('Week 3 & more');
  for (const id of ['exact-r', 'metal-grazing']) await page.locator(`#pick-${id}`).check();
  const downloading = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Save for an LMS (SCORM 1.2 zip)' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toBe('fresnel-lab-week-3-more-scorm12.zip');
  const files = unzipSync(new Uint8Array(readFileSync(await download.path())));
  expect(Object.keys(files).sort()).toEqual(['embed.html', 'favicon.svg', 'homework.html', 'imsmanifest.xml']);
  const manifest = strFromU8(files['imsmanifest.xml']);
  expect(manifest).toContain('<schemaversion>1.2</schemaversion>');
  expect(manifest).toContain('adlcp:scormtype="sco" href="homework.html"');
  expect(manifest).toContain('<title>Week 3 &amp; more</title>');

  // The package served as an LMS serves it, under its own folder, the stand-in LMS page above it.
  await page.route('**/lms/**', (route) => {
    const name = new URL(route.request().url()).pathname.split('/lms/')[1];
    if (name === 'player.html') return route.fulfill({ contentType: 'text/html', body: LMS });
    const file = files[name];
    return file ? route.fulfill({ contentType: name.endsWith('.svg') ? 'image/svg+xml' : 'text/html', body: Buffer.from(file) }) : route.fulfill({ status: 404 });
  });
  await page.goto('lms/player.html');
  const sco = page.frameLocator('#sco');
  const seed = `lms-${hashSeed('s123').toString(36)}`; // the learner's id, hashed
  await expect(sco.locator('.hw-seed')).toHaveText(seed);
  await expect(sco.getByLabel(/Lecture mode/)).toBeHidden(); // in a course, no switch that reveals answers
  await expect(sco.getByLabel(/Your name/)).toHaveValue('Lovelace, Ada');
  await expect(sco.getByText('handing in sends your score to its gradebook')).toBeVisible();
  await sco.locator('#question-2').getByRole('radio', { name: /Nearly white/ }).check();
  await sco.locator('#question-2').getByRole('button', { name: 'Check' }).click();
  await expect(sco.locator('#question-2 .hw-result')).toHaveText('Right.');
  const suspend = await page.evaluate(() => window.lmsData['cmi.suspend_data']);
  expect(JSON.parse(suspend)).toEqual({ seed, answers: [null, 'towards-white'] });
  await sco.getByRole('button', { name: /^Hand in/ }).click();
  await expect(sco.locator('.hw-hand-in-status')).toContainText('Your score, 1 of 2, went to the course\'s gradebook.');
  const data = await page.evaluate(() => window.lmsData);
  expect(data).toMatchObject({ 'cmi.core.score.raw': '50', 'cmi.core.score.min': '0', 'cmi.core.score.max': '100', 'cmi.core.lesson_status': 'completed' });
  expect((await page.evaluate(() => window.calls.map((c) => c[0])))[0]).toBe('LMSInitialize');
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
});
