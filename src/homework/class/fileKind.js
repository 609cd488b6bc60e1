// @ts-check
// Which files of a class are read, by name: a handed-in file (.json), text that holds codes (.txt),
// and zips (.zip) whose files are read the same way. Anything else is refused with its name, from a
// zip's directory before it is unpacked, so an LMS download with PDFs and photos costs nothing.

/** @typedef {'json' | 'text' | 'zip'} FileKind */

/** The last part of a path (a file in a zip or a dropped folder). */
export const baseName = (path) => path.slice(path.lastIndexOf('/') + 1);

/**
 * { kind } for a file that is read, or { reason } why it is not.
 * @param {string} path
 * @returns {{ kind: FileKind, reason?: undefined } | { kind?: undefined, reason: string }}
 */
export function fileKind(path) {
  const name = baseName(path);
  // A Mac's zip tool adds a resource-fork twin (__MACOSX/…/._handin.json) for every file: binary, no hand-in.
  if (path.split('/').includes('__MACOSX') || name.startsWith('._')) return { reason: 'macOS metadata that a Mac adds to '
    + 'zips, not a hand-in.' };
  const dot = name.lastIndexOf('.');
  const extension = dot > 0 ? name.slice(dot + 1).toLowerCase() : '';
  if (extension === 'json') return { kind: 'json' };
  if (extension === 'txt') return { kind: 'text' };
  if (extension === 'zip') return { kind: 'zip' };
  const what = extension ? `a .${extension.slice(0, 12)} file` : 'a file with no extension';
  return { reason: `not read: ${what} is no hand-in (handed-in files are .json, codes come in .txt files, and zips of them are opened).` };
}
