// Grade a class, as a lecturer does after the deadline: the sheet they set, then everything the class
// handed in at once (an LMS's zip with folders and a zip inside, loose files, pasted codes among
// other text), with what cannot be used among it. One page: the gradebook, refusals named, sorting
// and a report by keyboard, the CSV, a question shown to the class without names, the audit, markup
// in a name kept as text, and the view saved and opened again.
import { readFileSync } from 'node:fs';
import { strToU8, zipSync } from 'fflate';
import { test, expect } from './fixtures.js';
import { seriousViolations } from './audit.js';

const SHEET = { version: 1, title: 'Week 5', items: [{ question: 'brewster-predict' }, { question: 'exact-r' }, { question: 'metal-grazing' }] };
const code = (data) => Buffer.from(JSON.stringify(data)).toString('base64url');
const handIn = (name, seed, answers, time, sheet = SHEET) => ({
  kind: 'fresnel-lab-hand-in', version: 1, sheet, seed, name, answers, attempts: answers.map(() => 1), time,
});
const MARKUP = '<img src=x onerror="window.__xss=1">';
const students = Array.from({ length: 12 }, (_, i) => handIn(i === 5 ? MARKUP : `Student ${i + 1}`, `s${i + 1}`,
  [40 + i, i % 2 ? '0.5' : null, ['keeps-colour', 'towards-white', 'dark'][i % 3]], `2026-11-${String(10 + i).padStart(2, '0')}T10:00:00Z`));

test('a class handed in every way is graded at once: gradebook, refusals, report, CSV, the class view and saving it', async ({ page }) => {
  test.setTimeout(120_000);
  // An LMS's zip: a folder per student, one student's hand-in inside a zip of their own, a PDF.
  const zip = zipSync({
    ...Object.fromEntries(students.slice(0, 8).map((h, i) => [`Student ${i + 1}_${100 + i}_assignsubmission_file_/handin.json`, strToU8(JSON.stringify(h))])),
    'Student 9_108_assignsubmission_file_/work.zip': zipSync({ 'handin.json': strToU8(JSON.stringify(students[8])) }),
    'Student 10_109_assignsubmission_file_/notes.pdf': strToU8('%PDF-1.4'),
  });
  const later = handIn('Student 2', 's2', [50, '0.1', 'towards-white'], '2026-12-01T10:00:00Z'); // handed in again
  const otherSheet = handIn('Student 11', 's11', [40, null, null], '2026-11-20T10:00:00Z', { ...SHEET, title: 'Week 4' });
  const pasted = [
    'Name,Submission', `"Student 12","FLH1.${code(students[11])}"`, `Student 10: FLH1.${code(students[9])}`,
    `cut short: FLH1.${code(students[10]).slice(0, 40)}`,
  ].join('\n');

  await page.goto('homework.html');
  await page.getByLabel('The sheet the class answered').fill(`homework.html?sheet=${code(SHEET)}`);
  await page.getByLabel('Or paste codes (FLH1.…), one per line or among other text').fill(pasted);
  await page.getByLabel('Handed-in files, text files of codes, or zips').setInputFiles([
    { name: 'class.zip', mimeType: 'application/zip', buffer: Buffer.from(zip) },
    { name: 'late.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(later)) },
    { name: 'week4.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(otherSheet)) },
  ]);
  const status = page.locator('.hw-class-status');
  await expect(status).toContainText('Graded in', { timeout: 60_000 });
  await page.evaluate(() => window.fresnelLab.homework.classView.table.ready);
  // 11 students (12 minus the one cut short) and Student 2's earlier hand-in, kept but not counted.
  await expect(status).toContainText('12 hand-ins graded, 11 students counted (1 earlier hand-in not counted)');
  await expect(status).toContainText('Graded in a worker'); // the page's thread only shows the result
  await expect(status).toContainText(/Graded in a worker in (under 0\.1 s|\d+\.\d s)\.$/); // never "0.0 s"
  const rows = page.locator('.hw-gradebook .hw-body [role="row"]');
  await expect(rows).toHaveCount(12);
  await expect(page.locator('.hw-superseded')).toHaveCount(1);
  await expect(page.locator('.hw-superseded [role="rowheader"]')).toContainText('Student 2');
  const refused = page.locator('.hw-refused');
  await expect(refused).toContainText('notes.pdf');
  await expect(refused).toContainText('week4.json');
  await expect(refused).toContainText(/pasted text.*line 4/);
  expect(await page.evaluate(() => window.__xss)).toBeUndefined();
  await expect(page.locator('.hw-gradebook img')).toHaveCount(0);
  await expect(page.locator('.hw-gradebook')).toContainText(MARKUP);

  // Sorting and a report, from the keyboard.
  await page.getByRole('button', { name: 'Score: sort' }).focus();
  await page.keyboard.press('Enter');
  await expect(page.locator('[role="columnheader"][aria-sort="descending"]')).toContainText('Score');
  const scores = await page.locator('.hw-gradebook .hw-body .hw-points').allTextContents();
  const points = scores.map((s) => Number(s.split('/')[0]));
  expect(points).toEqual([...points].sort((a, b) => b - a));
  const report = page.getByRole('button', { name: 'Report of Student 3' });
  await report.focus();
  await page.keyboard.press('Enter');
  const dialog = page.getByRole('dialog', { name: 'Report: Student 3' });
  await expect(dialog).toBeVisible();
  await expect(dialog.locator('.hw-report-table tbody tr')).toHaveCount(3);
  expect(await seriousViolations(page), 'audit with a report open').toEqual([]);
  await page.keyboard.press('Escape');
  await expect(dialog).toBeHidden();
  await expect(report).toBeFocused();
  await expect(page.locator('.hw-report-table')).toHaveCount(0); // reports are made when opened

  // The CSV: UTF-8 with a byte-order mark, a column per question, a row per hand-in.
  const csvDownload = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Export CSV', exact: true }).click();
  const csv = readFileSync(await (await csvDownload).path(), 'utf8');
  expect(csv.startsWith('\ufeffName,')).toBe(true);
  const lines = csv.trim().split('\r\n');
  expect(lines[0]).toContain('Q1 brewster-predict');
  expect(lines[0]).toContain('Q3 metal-grazing');
  expect(lines).toHaveLength(13);
  // The same with semicolons, for a spreadsheet that writes 87,5: the percent with a decimal comma, local times.
  const semiDownload = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Export CSV with semicolons' }).click();
  const semi = readFileSync(await (await semiDownload).path(), 'utf8').replace(/^\ufeff/, '').trim().split('\r\n').map((l) => l.split(';'));
  expect(semi[0].slice(0, 7)).toEqual(['Name', 'LMS name', 'LMS user id', 'Seed', 'Score', 'Out of', 'Percent']);
  expect(semi).toHaveLength(13);
  const at = semi[0].indexOf('Handed in (local time)');
  for (const cells of semi.slice(1)) {
    expect(cells).toHaveLength(semi[0].length);
    expect(cells[6]).toMatch(/^\d+,\d$/);
    expect(cells[at]).toMatch(/^\d{4}-\d\d-\d\d \d\d:\d\d$/);
  }

  // One question shown to the class: its counts, no student's name.
  await page.getByRole('button', { name: 'Show question 3 to the class (no names)' }).click();
  const shown = page.getByRole('dialog', { name: 'Week 5: question 3' });
  await expect(shown).toContainText('of 11 students');
  const text = await shown.textContent();
  for (const h of students) expect(text).not.toContain(h.name);
  expect(await seriousViolations(page), 'audit with a question shown').toEqual([]);
  await page.keyboard.press('Escape');

  // Saved and opened again (the file holds no grade: everything is graded again).
  const savedDownload = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Save the class view' }).click();
  const saved = readFileSync(await (await savedDownload).path());
  await page.reload();
  await page.getByLabel('Or open a class view saved before').setInputFiles({ name: 'class.json', mimeType: 'application/json', buffer: saved });
  await expect(status).toContainText('12 hand-ins graded, 11 students counted', { timeout: 60_000 });
  await expect(rows).toHaveCount(12);
});

test('grading a class needs the sheet that was set, and says so', async ({ page }) => {
  await page.goto('homework.html');
  await page.getByLabel('Or paste codes (FLH1.…), one per line or among other text').fill(`FLH1.${code(students[0])}`);
  await page.getByRole('button', { name: 'Grade the class' }).click();
  await expect(page.locator('.hw-class-out [role="alert"]')).toContainText('Give the sheet you set');
  await expect(page.locator('.hw-gradebook')).toHaveCount(0);
});

test('a Moodle and a Canvas download are graded with every student named, and each LMS gets its grade import', async ({ page }) => {
  test.setTimeout(120_000);
  const sheet = { version: 1, title: 'Week 5', items: SHEET.items };
  const hand = (name, seed, time = '2026-11-10T10:00:00Z') => handIn(name, seed, [45, '0.5', 'towards-white'], time);
  const page1 = (body) => `<!DOCTYPE html><html><head><meta charset="UTF-8"></head><body>${body}</body></html>`;
  const moodle = zipSync({
    'Ada Lovelace_100001_assignsubmission_file_/handin.json': strToU8(JSON.stringify(hand('Ada Lovelace', 'm1'))),
    'Seán O Brien_100002_assignsubmission_onlinetext_/onlinetext.html': strToU8(page1(`<p>My code:</p><p>FLH1.${code(hand('', 'm2'))}</p>`)),
    '李伟_100003_assignsubmission_file_/handin': strToU8(JSON.stringify(hand('李伟', 'm3'))),
  });
  const canvas = zipSync({
    'bergbo_12345_900001_handin.json': strToU8(JSON.stringify(hand('Bo Berg', 'c1'))),
    'bergbo_LATE_12345_900002_handin-1.json': strToU8(JSON.stringify(hand('Bo Berg', 'c1', '2026-11-12T10:00:00Z'))),
    'kicy_LATE_23456_900003_handin.json': strToU8(JSON.stringify(hand('', 'c2'))),
    'nowakola_34567_text.html': strToU8(`<p>FLH1.${code(hand('Ola Nowak', 'c3'))}</p>`),
  });
  await page.goto('homework.html');
  await page.getByLabel('The sheet the class answered').fill(`homework.html?sheet=${code(sheet)}`);
  await page.getByLabel('Or paste codes (FLH1.…), one per line or among other text').fill(`FLH1.${code(hand('Di Rossi', 'p1'))}`);
  await page.getByLabel('Handed-in files, text files of codes, or zips').setInputFiles([
    { name: 'Week 5-42.zip', mimeType: 'application/zip', buffer: Buffer.from(moodle) },
    { name: 'course-week-5 submissions.zip', mimeType: 'application/zip', buffer: Buffer.from(canvas) },
  ]);
  const status = page.locator('.hw-class-status');
  await expect(status).toContainText('8 hand-ins graded, 7 students counted (1 earlier hand-in not counted)', { timeout: 60_000 });
  await page.evaluate(() => window.fresnelLab.homework.classView.table.ready);
  await expect(page.locator('.hw-refused')).toHaveCount(0);
  const names = await page.locator('.hw-gradebook .hw-body .hw-name').allTextContents();
  expect(names.map((n) => n.replace(' (not counted)', '')).sort()).toEqual(
    ['Ada Lovelace', 'Bo Berg', 'Bo Berg', 'Di Rossi', 'Ola Nowak', 'Seán O Brien', 'kicy', '李伟']);

  const save = async (name) => {
    const downloading = page.waitForEvent('download');
    await page.getByRole('button', { name }).click();
    return readFileSync(await (await downloading).path(), 'utf8').replace(/^\ufeff/, '').trim().split('\r\n').map((line) => line.split(','));
  };
  await page.getByLabel(/Out of: the assignment’s maximum grade/).fill('10');
  const worksheet = await save('Moodle grading worksheet');
  expect(worksheet[0]).toEqual(['Identifier', 'Full name', 'Grade', 'Maximum grade', 'Last modified (submission)', 'Last modified (grade)']);
  expect(worksheet.slice(1).map((r) => [r[0], r[1], r[3]]).sort()).toEqual([
    ['Participant 100001', 'Ada Lovelace', '10'], ['Participant 100002', 'Seán O Brien', '10'], ['Participant 100003', '李伟', '10']]);
  const lmsStatus = page.locator('.hw-lms-status');
  await expect(lmsStatus).toHaveText('Saved for Moodle: 3 students, graded out of 10. Not in the file, to grade by hand: 4 students.');
  await expect(page.locator('.hw-lms-left')).toContainText('Di Rossi: no Moodle participant number in the path of their hand-in (pasted text, line 1).');
  const imported = await save('Canvas gradebook import');
  expect(imported.slice(0, 2)).toEqual([['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section', 'Week 5'], ['Points Possible', '', '', '', '', '10']]);
  expect(imported.slice(2).map((r) => [r[0], r[1]]).sort()).toEqual([['Bo Berg', '12345'], ['Ola Nowak', '34567'], ['kicy', '23456']]);
  await expect(lmsStatus).toContainText('Saved for Canvas: 3 students');
});

test('"Show the class" opens at the question, with the focus on it, on a 1280×720 projector', async ({ page }) => {
  await page.setViewportSize({ width: 1280, height: 720 });
  await page.goto('homework.html');
  await page.getByLabel('The sheet the class answered').fill(`homework.html?sheet=${code(SHEET)}`);
  await page.getByLabel('Or paste codes (FLH1.…), one per line or among other text').fill(students.map((h) => `FLH1.${code(h)}`).join('\n'));
  await page.getByRole('button', { name: 'Grade the class' }).click();
  const show = page.getByRole('button', { name: 'Show question 2 to the class (no names)' });
  await show.click();
  const dialog = page.getByRole('dialog', { name: 'Week 5: question 2' });
  await expect(dialog).toBeVisible();
  // Taller than the screen (else this shows nothing), yet open at its top: the heading has the focus, the question is in view.
  expect(await dialog.evaluate((d) => d.scrollHeight > d.clientHeight)).toBe(true);
  await expect(dialog.getByRole('heading', { name: 'Week 5: question 2' })).toBeFocused();
  expect(await dialog.evaluate((d) => d.scrollTop)).toBe(0);
  await expect(dialog.locator('.hw-prompt')).toBeInViewport();
  await page.keyboard.press('Tab');
  await expect(dialog.getByRole('button', { name: 'Close' })).toBeFocused();
  await page.keyboard.press('Enter');
  await expect(dialog).toBeHidden();
  await expect(show).toBeFocused();
});

test('the flags are explained under the gradebook, the copied-answers rule with its numbers', async ({ page }) => {
  const sheet = { version: 1, title: 'Week 6', items: [{ question: 'exact-r' }, { question: 'r0-value' }, { question: 'brewster-predict' }] };
  const same = ['0.9', '0.9', 10]; // the same wrong answers on the same seed: copied, or one sheet under two names
  const hand = (name, seed, answers) => handIn(name, seed, answers, '2026-11-10T10:00:00Z', sheet);
  const codes = [hand('Ann', 'twin', same), hand('Ben', 'twin', same), hand('Cy', 'c', same), hand('', 'd', [null, null, null])];
  await page.goto('homework.html');
  await page.getByLabel('The sheet the class answered').fill(`homework.html?sheet=${code(sheet)}`);
  await page.getByLabel('Or paste codes (FLH1.…), one per line or among other text').fill(codes.map((h) => `FLH1.${code(h)}`).join('\n'));
  await page.getByRole('button', { name: 'Grade the class' }).click();
  const legend = page.getByRole('list', { name: 'What the flags mean' });
  await expect(legend.getByRole('listitem')).toHaveText([
    /^shared seed one seed under two or more names/,
    /^same wrong answers two students on one seed gave the same wrong answer to 3 or more number or prediction questions, as a copied sheet does\. A wrong answer that 4 or more students give is taken for a common slip and not counted\.$/,
    /^no name the hand-in gives no name/,
  ]);
  await page.getByRole('button', { name: 'Report of Ann' }).click();
  await expect(page.getByRole('dialog', { name: 'Report: Ann' }).locator('.hw-flag-list')).toContainText('Flagged at 3 or more such questions');
});
