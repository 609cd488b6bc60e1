// "Grade a class" on the built homework page, for npm run bench: a synthetic class
// (src/homework/class/syntheticClass.js) brought as its LMS zip (and as pasted codes), each run in a
// fresh browser context (a cold cache, a worker started anew), timed from just before the input
// gets the files to the moment the status says "Graded in", every gradebook row is made
// (classView.table.ready) and every question's card is there. Meanwhile, the worst of all runs:
// the longest task on the page's thread, script (longtask entries) or a frame's rendering
// (long-animation-frame entries), 0 when none passed 50 ms, with the longest frame's scripts and
// rendering. And how much the page grows per student: about one gradebook row, since a student's
// report is built only when opened (the run fails if one was, or if rows or cards are missing).
import { createServer } from 'vite';
import { freshContext, spread } from './measurePages.js';

/** The synthetic class and the sheet's link, made in Node through vite (the sheet reader uses import.meta.glob). */
async function makeClass(root, students, questions) {
  const server = await createServer({ root, logLevel: 'error', appType: 'custom', server: { middlewareMode: true, hmr: false, ws: false } });
  try {
    const { syntheticClass } = await server.ssrLoadModule('/src/homework/class/syntheticClass.js');
    const { sheetToCode } = await server.ssrLoadModule('/src/homework/sheetCodes.js');
    const made = syntheticClass({ students, questions, seed: 'bench' });
    return { zip: Buffer.from(made.zip), codes: made.codes, handIns: made.handIns.length, link: `homework.html?sheet=${sheetToCode(made.sheet)}` };
  } finally {
    await server.close();
  }
}

/**
 * One run: a fresh page, the sheet's link, `prepare(page)` (untimed), then `bring(page)` hands in
 * the class and returns the page's clock when it began; returns what was measured.
 */
async function oneRun(browser, base, made, { prepare = async () => {}, bring }) {
  const context = await freshContext(browser, { width: 1280, height: 800 });
  try {
    const page = await context.newPage();
    // Long tasks count script tasks only: a frame's rendering (style, layout, paint of the growing
    // table) is a task of its own that only a long animation frame's entry shows, from renderStart.
    await page.addInitScript(() => {
      window.__longTasks = [];
      window.__renders = [];
      new PerformanceObserver((list) => { window.__longTasks.push(...list.getEntries().map((e) => ({ start: e.startTime, duration: e.duration }))); })
        .observe({ type: 'longtask', buffered: true });
      window.__frames = [];
      if (PerformanceObserver.supportedEntryTypes.includes('long-animation-frame')) {
        new PerformanceObserver((list) => {
          for (const e of list.getEntries()) {
            const end = e.startTime + e.duration;
            const render = e.renderStart > 0 ? end - e.renderStart : 0;
            if (render > 50) window.__renders.push({ start: e.renderStart, duration: render });
            // What the frame spent its time on, to say where a long one went (its duration may
            // span several tasks and the waits between them).
            window.__frames.push({
              start: e.startTime, duration: e.duration, renderMs: render, styleAndLayoutMs: e.styleAndLayoutStart > 0 ? end - e.styleAndLayoutStart : 0,
              scripts: e.scripts.map((x) => ({ ms: x.duration, what: `${x.invoker} ${x.sourceFunctionName || ''} ${x.sourceURL.split('/').pop()}:${x.sourceCharPosition}`.replace(/\s+/g, ' ') })),
            });
          }
        }).observe({ type: 'long-animation-frame', buffered: true });
      }
    });
    await page.goto(`${base}homework.html`);
    await page.waitForFunction(() => window.fresnelLab?.homework?.classView);
    await page.locator('.hw-class').getByLabel(/^The sheet/).fill(made.link);
    await prepare(page);
    // The end is seen in the page (no polling from here to load its thread): the status's text,
    // then every row, then the cards, which are appended in the same task as the table.
    const before = await page.evaluate(() => {
      const state = window.fresnelLab.homework.classView;
      const status = document.querySelector('.hw-class-status');
      window.__classDone = new Promise((resolve) => {
        const observer = new MutationObserver(async () => {
          if (!status.textContent.includes('Graded in') || !state.table) return;
          observer.disconnect();
          await state.table.ready;
          resolve(performance.now());
        });
        observer.observe(status, { childList: true, characterData: true, subtree: true });
      });
      return document.getElementsByTagName('*').length;
    });
    const t0 = await bring(page);
    const done = await page.evaluate(() => window.__classDone);
    // A long task's entry comes after the task: let the observer hear of the last one.
    await page.evaluate(() => new Promise((resolve) => { setTimeout(resolve, 100); }));
    return await page.evaluate(({ start, end }) => {
      const state = window.fresnelLab.homework.classView;
      const rows = document.querySelectorAll('.hw-gradebook .hw-body [role="row"]');
      const inRows = [...rows].reduce((n, tr) => n + tr.getElementsByTagName('*').length + 1, 0);
      const meanwhile = (list) => list.filter((t) => t.start + t.duration >= start && t.start <= end);
      const longest = (list) => meanwhile(list).reduce((m, t) => Math.max(m, t.duration), 0);
      const frame = meanwhile(window.__frames).reduce((a, f) => (f.duration > (a?.duration ?? 0) ? f : a), null);
      return {
        wallMs: end - start,
        longestScriptTaskMs: longest(window.__longTasks),
        longestRenderMs: longest(window.__renders),
        longestFrame: frame && { ...frame, start: frame.start - start, scripts: frame.scripts.sort((a, b) => b.ms - a.ms).slice(0, 4) },
        elements: document.getElementsByTagName('*').length,
        rows: rows.length,
        elementsPerRow: rows.length ? inRows / rows.length : 0,
        cards: document.querySelectorAll('.hw-class-question').length,
        reportBuilt: document.querySelector('.hw-student-dialog .hw-dialog-body').childElementCount > 0,
        graded: state.view?.gradebook.rows.length ?? 0,
        status: document.querySelector('.hw-class-status').textContent,
      };
    }, { start: t0, end: done }).then((r) => ({ ...r, elementsBefore: before }));
  } finally {
    await context.close();
  }
}

/** The zip, set on the input (its change starts grading): timed from just before it is set. */
const fromZip = (made) => ({
  async bring(page) {
    const input = page.locator('.hw-class').getByLabel('Handed-in files, text files of codes, or zips');
    await input.waitFor();
    const t0 = await page.evaluate(() => performance.now());
    await input.setInputFiles({ name: 'class.zip', mimeType: 'application/zip', buffer: made.zip });
    return t0;
  },
});

/** The codes, pasted before the clock starts; timed from the button's click, made in the page. */
const fromCodes = (made) => ({
  prepare: (page) => page.locator('.hw-class').getByLabel('Or paste codes (FLH1.…), one per line or among other text').fill(made.codes),
  bring: (page) => page.locator('.hw-class').getByRole('button', { name: 'Grade the class' }).evaluate((button) => {
    const t0 = performance.now();
    button.click();
    return t0;
  }),
});

/**
 * Grade a class of `students` hand-ins of a `questions`-question sheet, `runs` times from the zip
 * and `codeRuns` times from pasted codes.
 */
export async function classView(browser, base, root, { students = 500, questions = 40, runs = 5, codeRuns = 3 } = {}) {
  const made = await makeClass(root, students, questions);
  const summarise = (samples, source) => {
    for (const s of samples) {
      if (s.rows !== made.handIns || s.graded !== made.handIns || s.cards !== questions || s.reportBuilt) {
        throw new Error(`class view from ${source}: ${s.rows} rows and ${s.graded} graded of ${made.handIns} hand-ins, ${s.cards} of ${questions} cards`
          + `${s.reportBuilt ? ', a report built unasked' : ''} (${s.status})`);
      }
    }
    const last = samples[samples.length - 1];
    return {
      source, runs: samples.length,
      wallMs: spread(samples.map((s) => s.wallMs)),
      longestTaskMs: Math.max(...samples.map((s) => Math.max(s.longestScriptTaskMs, s.longestRenderMs))),
      longestScriptTaskMs: Math.max(...samples.map((s) => s.longestScriptTaskMs)),
      longestRenderMs: Math.max(...samples.map((s) => s.longestRenderMs)),
      longestFrame: samples.map((s) => s.longestFrame).reduce((a, f) => ((f?.duration ?? 0) > (a?.duration ?? 0) ? f : a), null),
      elementsPerStudent: (last.elements - last.elementsBefore) / students,
      elementsPerRow: last.elementsPerRow,
      rows: last.rows,
      where: /Graded in (a worker|the page’s thread)/.exec(last.status)?.[1] ?? '?',
      samples: samples.map((s) => s.wallMs),
    };
  };
  const zipSamples = [];
  for (let r = 0; r < runs; r += 1) zipSamples.push(await oneRun(browser, base, made, fromZip(made)));
  const result = { students, questions, ...summarise(zipSamples, 'zip') };
  if (codeRuns > 0) {
    const codeSamples = [];
    for (let r = 0; r < codeRuns; r += 1) {
      codeSamples.push(await oneRun(browser, base, made, fromCodes(made)));
    }
    result.codes = summarise(codeSamples, 'codes');
  }
  return result;
}
