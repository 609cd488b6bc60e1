// @ts-check
// The gradebook of a graded class: one row per hand-in, each marked whether it counts, with flags
// for what a lecturer should look at before the grades go anywhere:
//   superseded / resubmitted  the same student handed in more than once: the latest (by the time in
//                             the hand-in) counts, the others stay as rows that do not count;
//   shared-seed               one seed under two names (a sheet without a class seed gives each
//                             student their own seed, so two names on one seed handed in one sheet);
//   class-seed                a seed other than the class seed (gradeHandIn refuses those, so this
//                             shows only for grades made some other way);
//   copied                    the same wrong numbers to the same numbers: two students on one seed
//                             with the same wrong answer to several numeric or predict questions;
//   no-name                   the hand-in gives no name.
// A student is their id in the LMS the hand-in came from where its path gives one (the participant
// number in a Moodle folder's name, the user id in a Canvas file's name, the user name in a
// Blackboard file's name): two students of one name are two students. A hand-in without one (a code
// pasted from a mail) is the student's whose LMS hand-ins give its name (spaces and case aside), if
// they are one student's; else the name alone says who it is. Hand-ins with neither are never taken
// for one another.
import { knownQuestion } from '../questions.js';
import { lmsUser } from './lmsName.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

/**
 * @typedef {'right' | 'wrong' | 'unanswered'} Mark
 * @typedef {{ kind: 'superseded' | 'resubmitted' | 'shared-seed' | 'class-seed' | 'copied' | 'no-name', text: string,
 *   others: number[] }} Flag
 * @typedef {{ key: number, name: string, lmsName: string, lms: import('./lmsName.js').LmsUser['lms'], lmsId: string, seed: string,
 *   score: number, total: number, percent: number, marks: Mark[], tries: (number | null)[], triesTotal: number | null,
 *   time: string | null, source: string, counted: boolean, flags: Flag[] }} Row
 *   key: the hand-in's index in grades.graded; lms, lmsId: the LMS and the student's id there, from the source's path
 * @typedef {{ title: string, fingerprint: string, classSeed: string | null, items: { question: string, kind: string }[],
 *   rows: Row[], students: number, superseded: number, copiedRule: { atLeast: number, common: number } }} Gradebook
 *   copiedRule: the copied flag's rule: how many questions with the same wrong answer flag a pair, and how many
 *   students giving one wrong answer make it a common slip, left out
 * @typedef {(row: Row) => string | null} Identity  who a row's student is, or null where nothing says
 * @typedef {import('./gradeClass.js').Graded} Graded
 */

const t = messages('class', english);
const COPIED_AT_LEAST = 3;
const normalName = (/** @type {string} */ text) => text.normalize('NFC').trim().replace(/\s+/g, ' ').toLocaleLowerCase();
const shown = (/** @type {Row} */ row) => row.name || row.lmsName || row.source;
const listed = (/** @type {Row[]} */ rows) => rows.map(shown).join(', ');
const timeOf = (/** @type {Row} */ row) => (row.time === null ? -Infinity : Date.parse(row.time));

/**
 * The same student more than once: the latest counts (the later one in the list when the times agree).
 * @param {Row[]} rows
 * @param {Identity} identity
 */
function supersede(rows, identity) {
  /** @type {Map<string, Row[]>} */
  const byStudent = new Map();
  for (const row of rows) {
    const who = identity(row);
    if (who === null) continue;
    const group = byStudent.get(who) ?? [];
    byStudent.set(who, group);
    group.push(row);
  }
  for (const group of byStudent.values()) {
    if (group.length < 2) continue;
    group.sort((a, b) => timeOf(a) - timeOf(b) || a.key - b.key);
    const latest = group[group.length - 1];
    const earlier = group.slice(0, -1);
    for (const row of earlier) {
      row.counted = false;
      const text = t('flag.superseded.text', {
        name: shown(latest), hasTime: latest.time === null ? 'no' : 'yes', time: latest.time, source: latest.source,
      });
      row.flags.push({ kind: 'superseded', text, others: [latest.key] });
    }
    latest.flags.push({
      kind: 'resubmitted', text: t('flag.resubmitted.text', { count: group.length }), others: earlier.map((r) => r.key),
    });
  }
}

/**
 * One seed under more than one student (only where the sheet gives no class seed).
 * @param {Row[]} rows
 * @param {Identity} identity
 */
function sharedSeeds(rows, identity) {
  /** @type {Map<string, Row[]>} */
  const bySeed = new Map();
  for (const row of rows) {
    const group = bySeed.get(row.seed) ?? [];
    bySeed.set(row.seed, group);
    group.push(row);
  }
  for (const group of bySeed.values()) {
    const students = new Set(group.map((row) => identity(row) ?? `#${row.key}`));
    if (students.size < 2) continue;
    for (const row of group) {
      const others = group.filter((r) => r !== row);
      const text = t('flag.shared-seed.text', { seed: row.seed, others: listed(others), count: students.size });
      row.flags.push({ kind: 'shared-seed', text, others: others.map((r) => r.key) });
    }
  }
}

/**
 * Pairs with the same wrong answers to the same numbers on `atLeast` numeric or predict questions.
 * A wrong answer that many share (a common slip, such as R(0°) for R) says nothing about copying, so
 * one shared by more than 5 % of the class (at least 4 students) is left out; this also keeps the
 * pairs counted small.
 * @param {Row[]} rows
 * @param {readonly Graded[]} graded
 * @param {{ question: string, kind: string }[]} items
 * @param {Identity} identity
 * @param {number} atLeast
 */
function copiedAnswers(rows, graded, items, identity, atLeast) {
  /** @type {Map<string, { item: number, rows: Row[] }>} */
  const buckets = new Map();
  for (const row of rows) {
    graded[row.key].result.results.forEach((r, i) => {
      if (!r.answered || r.correct || items[i].kind === 'choice') return;
      const value = items[i].kind === 'numeric' ? r.value : r.answer;
      const key = `${row.seed}\u0000${i}\u0000${value}`;
      const bucket = buckets.get(key) ?? { item: i, rows: [] };
      buckets.set(key, bucket);
      bucket.rows.push(row);
    });
  }
  const common = commonSlip(rows.length);
  /** @type {Map<string, { x: Row, y: Row, items: number[] }>} */
  const pairs = new Map();
  for (const { item, rows: same } of buckets.values()) {
    if (same.length < 2 || same.length >= common) continue;
    for (let a = 0; a < same.length; a += 1) {
      for (let b = a + 1; b < same.length; b += 1) {
        const [x, y] = [same[a], same[b]];
        if (identity(x) !== null && identity(x) === identity(y)) continue;
        const key = `${Math.min(x.key, y.key)}:${Math.max(x.key, y.key)}`;
        const pair = pairs.get(key) ?? { x, y, items: [] };
        pairs.set(key, pair);
        pair.items.push(item);
      }
    }
  }
  for (const { x, y, items: shared } of pairs.values()) {
    if (shared.length < atLeast) continue;
    const questions = shared.sort((a, b) => a - b).map((i) => i + 1).join(', ');
    for (const [row, other] of /** @type {[Row, Row][]} */ ([[x, y], [y, x]])) {
      const text = t('flag.copied.text', { name: shown(other), seed: row.seed, questions, atLeast, common });
      row.flags.push({ kind: 'copied', text, others: [other.key] });
    }
  }
}

/** A row's student in its LMS: its id there, or a Blackboard user name (unique in Blackboard); null where the path gives neither. */
const lmsKey = (/** @type {Row} */ row) => (row.lmsId ? `${row.lms}\u0000${row.lmsId}`
  : row.lms === 'blackboard' && row.lmsName ? `blackboard\u0000${normalName(row.lmsName)}` : null);

/**
 * Who each row's student is: their LMS key; for a row without one, the LMS key of the one student
 * whose rows give its name (typed or in the LMS's path), else the name itself.
 * @param {Row[]} rows
 * @returns {Identity}
 */
function identities(rows) {
  /** @type {Map<string, Set<string>>} */
  const byName = new Map();
  for (const row of rows) {
    const key = lmsKey(row);
    if (key === null) continue;
    for (const name of [row.name, row.lmsName].filter(Boolean).map(normalName)) {
      const keys = byName.get(name) ?? new Set();
      byName.set(name, keys);
      keys.add(key);
    }
  }
  /** @type {Map<Row, string | null>} */
  const who = new Map();
  for (const row of rows) {
    const key = lmsKey(row);
    const name = row.name ? normalName(row.name) : '';
    const keys = name ? byName.get(name) : undefined;
    // Two students of that name in the LMS: the hand-in could be either's, so it is neither's.
    who.set(row, key ?? (keys?.size === 1 ? [...keys][0] : name ? `name\u0000${name}` : null));
  }
  return (row) => who.get(row) ?? null;
}

/** How many students giving one wrong answer make it a common slip: 5 % of the class, at least 4. */
const commonSlip = (/** @type {number} */ students) => Math.max(4, Math.ceil(0.05 * students));

/**
 * The gradebook of a class graded by gradeClass (its { ok: true, … } result). copiedAtLeast: how
 * many identical wrong answers flag a pair (3).
 * @param {{ sheet: import('../readSheet.js').Sheet, fingerprint: string, graded: readonly Graded[] }} grades
 * @param {{ copiedAtLeast?: number }} [options]
 * @returns {Gradebook}
 */
export function buildGradebook(grades, { copiedAtLeast = COPIED_AT_LEAST } = {}) {
  const { sheet, graded } = grades;
  const items = sheet.items.map((item) => ({ question: item.question, kind: knownQuestion(item.question).kind }));
  /** @type {Row[]} */
  const rows = graded.map(({ source, result }, key) => {
    const tries = result.results.map((r) => r.attempts);
    const known = tries.filter((t) => t !== null);
    const lms = lmsUser(source);
    return {
      key, name: result.name, lmsName: lms.name, lms: lms.lms, lmsId: lms.id, seed: result.seed,
      score: result.score, total: result.total, percent: result.total ? (100 * result.score) / result.total : 0,
      marks: result.results.map((r) => (r.correct ? 'right' : r.answered ? 'wrong' : 'unanswered')),
      tries, triesTotal: known.length ? known.reduce((a, b) => a + b, 0) : null,
      time: result.time, source, counted: true, flags: [],
    };
  });
  const identity = identities(rows);
  supersede(rows, identity);
  const counted = rows.filter((row) => row.counted);
  if (sheet.seed === undefined) sharedSeeds(counted, identity);
  else {
    for (const row of counted) {
      if (row.seed === sheet.seed) continue;
      row.flags.push({ kind: 'class-seed', text: t('flag.class-seed.text', { seed: row.seed, classSeed: sheet.seed }), others: [] });
    }
  }
  copiedAnswers(counted, graded, items, identity, copiedAtLeast);
  for (const row of rows) {
    if (!row.name) {
      const text = t('flag.no-name.text', { hasLmsName: row.lmsName ? 'yes' : 'no', lmsName: row.lmsName });
      row.flags.push({ kind: 'no-name', text, others: [] });
    }
  }
  return {
    title: sheet.title, fingerprint: grades.fingerprint, classSeed: sheet.seed ?? null, items, rows,
    students: counted.length, superseded: rows.length - counted.length,
    copiedRule: { atLeast: copiedAtLeast, common: commonSlip(counted.length) },
  };
}
