#!/usr/bin/env node
// node bench/classBench.js [--students 500] [--questions 40] [--runs 7]
// How long a class view takes in Node: a synthetic class (src/homework/class/syntheticClass.js) read
// from its LMS zip, from separate files and from pasted codes, graded and summarised. The modules
// are loaded through vite (the sheet reader finds the panels' schemas with import.meta.glob). The
// class is made by one copy of the modules and measured on another, so the first run starts with
// empty per-question caches (gradeAnswer.js), as a page does: it is reported on its own, with its
// longest slice of grading (what a page's thread would hold at once); later runs give the median
// and the spread.
import { createServer } from 'vite';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i < 0 ? fallback : Number(args[i + 1]);
};
const students = option('students', 500);
const questions = option('questions', 40);
const runs = option('runs', 7);

const modules = async () => {
  const server = await createServer({ root, logLevel: 'error', appType: 'custom', server: { middlewareMode: true, hmr: false, ws: false } });
  const load = (path) => server.ssrLoadModule(`/src/homework/class/${path}`);
  return {
    server,
    ...(await load('syntheticClass.js')), ...(await load('readClassHandIns.js')), ...(await load('gradeClass.js')),
    ...(await load('buildGradebook.js')), ...(await load('summarizeQuestions.js')),
  };
};
const ms = (x) => `${x.toFixed(0)} ms`;
const stats = (list) => {
  const sorted = [...list].sort((a, b) => a - b);
  return `${ms(sorted[Math.floor(sorted.length / 2)])} (${sorted[0].toFixed(0)}–${ms(sorted[sorted.length - 1])})`;
};

const maker = await modules();
const measured = await modules();
try {
  let t = performance.now();
  const synthetic = maker.syntheticClass({ students, questions, seed: 'bench' });
  console.log(`${students} hand-ins of a ${questions}-question sheet made in ${ms(performance.now() - t)} (zip ${(synthetic.zip.length / 1024).toFixed(0)} KB, codes ${(synthetic.codes.length / 1024).toFixed(0)} KB)`);
  const { readClassHandIns, gradeClassSteps, buildGradebook, summarizeQuestions } = measured;
  const inputs = {
    zip: { files: [{ name: 'class.zip', bytes: synthetic.zip }] },
    files: { files: synthetic.files },
    codes: { text: synthetic.codes },
  };
  let cold = true;
  for (const [label, input] of Object.entries(inputs)) {
    const times = { read: [], grade: [], summarise: [], total: [], slice: [] };
    for (let run = 0; run < runs + 1; run += 1) {
      t = performance.now();
      const read = readClassHandIns(input);
      const t1 = performance.now();
      const steps = gradeClassSteps(synthetic.sheet, read.handIns); // slices of 40 ms, as on a page
      let longest = 0;
      let step;
      for (let from = performance.now(); ; from = performance.now()) {
        step = steps.next();
        longest = Math.max(longest, performance.now() - from);
        if (step.done) break;
      }
      const grades = step.value;
      const t2 = performance.now();
      const gradebook = buildGradebook(grades);
      summarizeQuestions(grades, gradebook);
      const t3 = performance.now();
      if (grades.graded.length !== students || read.refused.length || grades.refused.length) throw new Error(`${label}: ${grades.graded.length} graded, ${read.refused.length + grades.refused.length} refused`);
      const sample = { read: t1 - t, grade: t2 - t1, summarise: t3 - t2, total: t3 - t, slice: longest };
      if (run === 0) {
        const first = cold ? 'first run (empty caches)' : 'first run';
        console.log(`${label}: ${first} ${ms(sample.total)}: read ${ms(sample.read)}, grade ${ms(sample.grade)} (longest slice ${ms(longest)}), gradebook and summary ${ms(sample.summarise)}`);
        cold = false;
        continue;
      }
      for (const key of Object.keys(times)) times[key].push(sample[key]);
    }
    console.log(`${label}: median of ${runs} later runs ${stats(times.total)}: read ${stats(times.read)}, grade ${stats(times.grade)}, gradebook and summary ${stats(times.summarise)}; longest slice ${stats(times.slice)}`);
  }
} finally {
  await maker.server.close();
  await measured.server.close();
}
