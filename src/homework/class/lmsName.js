// @ts-check
// The student an LMS names in a hand-in's path, when it does: "download all submissions" puts each
// student's files in a folder or under a file name that carries their name and their id in that
// LMS. The name is shown beside the one the hand-in gives (a copied file keeps its first owner's
// name, the LMS's folder does not); the id is what the LMS's grade import finds the student by
// (lmsGrades.js), and tells hand-ins without a name apart. Best effort: no name and no id when no
// pattern fits.
//   Moodle (mod/assign/locallib.php, download_submissions: the full name with "_" made spaces, the
//   participant number, the plugin; in a folder each, or as a prefix of each file's name):
//     "Ada Lovelace_123456_assignsubmission_file_/handin.json"
//     "Ada Lovelace_123456_assignsubmission_onlinetext_/onlinetext.html"
//     "Ada Lovelace_123456_assignsubmission_file_handin.json"
//   Canvas (lib/content_zipper.rb, get_filename: the sortable name lower-cased with every character
//   that is not a letter, digit or "_" dropped, "LATE" for a late one, the user id, then the file's
//   id and name, or "text" for online text):
//     "lovelaceada_12345_67890_handin.json", "obrienseán_LATE_12345_67890_handin.json",
//     "lovelaceada_12345_text.html"
//   Blackboard (a user name, no id):
//     "Homework 3_alovelace_attempt_2026-01-02-10-00-00_handin.json"

const MOODLE = /^([^_/]+)_(\d+)_assignsubmission_[a-z]+_/i;
// An online text's page is the whole file name: what follows it in a source is the line a code was
// on (", line 3" in English, other words in another language), never more of the name.
const CANVAS = /^([\p{L}\p{M}\p{N}_]+?)_(?:late_)?(\d+)_(?:\d+_.|(?:text|link)\.html(?![\p{L}\p{N}._-]))/iu;
const BLACKBOARD = /_([^_/]+)_attempt_\d{4}-\d\d-\d\d/;

/**
 * @typedef {{ lms: 'moodle' | 'canvas' | 'blackboard' | '', name: string, id: string }} LmsUser
 *   id: Moodle's participant number or Canvas's user id ('' where the LMS gives none)
 */

/**
 * The student an LMS's path names: which LMS, their name (or user name) and id, or '' for each.
 * @param {string} source a hand-in's source (a path in a zip, perhaps the line of a code after it: ", line N")
 * @returns {LmsUser}
 */
export function lmsUser(source) {
  const parts = String(source).split('/');
  for (const part of parts) {
    const moodle = MOODLE.exec(part);
    if (moodle) return { lms: 'moodle', name: moodle[1].trim(), id: moodle[2] };
  }
  const file = parts[parts.length - 1];
  const canvas = CANVAS.exec(file);
  if (canvas) return { lms: 'canvas', name: canvas[1], id: canvas[2] };
  const blackboard = BLACKBOARD.exec(file);
  return blackboard ? { lms: 'blackboard', name: blackboard[1], id: '' } : { lms: '', name: '', id: '' };
}

/**
 * The student's name (or user name) in an LMS's path, or ''.
 * @param {string} source
 * @returns {string}
 */
export const lmsName = (source) => lmsUser(source).name;
