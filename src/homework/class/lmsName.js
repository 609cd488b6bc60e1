// @ts-check
// The student an LMS names in a hand-in's path, when it does: "download all submissions" puts each
// student's files in a folder or under a file name that carries their name. Shown beside the name
// the hand-in gives (a copied file keeps its first owner's name, the LMS's folder does not), and
// used to tell hand-ins apart when the file gives no name. Best effort: '' when no pattern fits.
//   Moodle:      "Ada Lovelace_12345_assignsubmission_file_/handin.json"
//   Canvas:      "lovelaceada_12345_67890_handin.json" (also "…_late_…")
//   Blackboard:  "Homework 3_alovelace_attempt_2026-01-02-10-00-00_handin.json"

const MOODLE = /^(.+?)_\d+_assignsubmission_[a-z]+_?$/i;
const CANVAS = /^([a-z]+)_(?:late_)?\d+_\d+_/;
const BLACKBOARD = /_([^_/]+)_attempt_\d{4}-\d\d-\d\d/;

/**
 * The student's name (or user name) in an LMS's path, or ''.
 * @param {string} source a hand-in's source (a path in a zip, perhaps ", line N" after it)
 * @returns {string}
 */
export function lmsName(source) {
  const parts = String(source).replace(/, line \d+$/, '').split('/');
  for (const part of parts) {
    const moodle = MOODLE.exec(part);
    if (moodle) return moodle[1].trim();
  }
  const file = parts[parts.length - 1];
  const canvas = CANVAS.exec(file);
  if (canvas) return canvas[1];
  const blackboard = BLACKBOARD.exec(file);
  return blackboard ? blackboard[1] : '';
}
