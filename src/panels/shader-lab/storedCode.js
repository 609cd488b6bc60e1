// @ts-check
// The student's code per exercise, kept in this browser (localStorage) as they type, so a closed
// page loses nothing; where storage is refused the link still carries the code.
const KEY = 'fresnel-lab:shader-lab:';

/**
 * The code kept for an exercise, or null (none kept, or storage refused).
 * @param {string} exerciseId
 * @returns {string | null}
 */
export function readStored(exerciseId) {
  try {
    return window.localStorage.getItem(KEY + exerciseId);
  } catch {
    return null;
  }
}

/**
 * Empty code (the exercise's start) removes the entry.
 * @param {string} exerciseId
 * @param {string} code
 */
export function writeStored(exerciseId, code) {
  try {
    if (code) window.localStorage.setItem(KEY + exerciseId, code);
    else window.localStorage.removeItem(KEY + exerciseId);
  } catch { /* refused: the link keeps it */ }
}
