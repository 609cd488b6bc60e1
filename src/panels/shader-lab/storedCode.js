// The student's code per exercise, kept in this browser (localStorage) as they type, so a closed
// page loses nothing; where storage is refused the link still carries the code.
const KEY = 'fresnel-lab:shader-lab:';

export function readStored(exerciseId) {
  try {
    return window.localStorage.getItem(KEY + exerciseId);
  } catch {
    return null;
  }
}

/** Empty code (the exercise's start) removes the entry. */
export function writeStored(exerciseId, code) {
  try {
    if (code) window.localStorage.setItem(KEY + exerciseId, code);
    else window.localStorage.removeItem(KEY + exerciseId);
  } catch { /* refused: the link keeps it */ }
}
