// @ts-check
// What a lecturer picked or dropped, as [{ name (its path), bytes }] for the class view: files from
// a picker, a folder (webkitdirectory gives each file its relative path), or items dropped, folders
// walked. A file larger than its kind may be is refused here, by name, without being read into
// memory; a kind that is never read is passed on empty and refused by name there (fileKind.js).
import { CLASS_CAPS, megabytes } from '../../class/classCaps.js';
import { contentKind, fileKind } from '../../class/fileKind.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../../i18n/messages.js';

const t = messages('class', english);

const MAX_WALKED = CLASS_CAPS.maxEntries; // files taken from dropped folders, as from a zip

/**
 * @param {{ file: File, path: string }[]} entries
 * @returns {Promise<{ files: { name: string, bytes: Uint8Array }[], refused: { source: string, reason: string }[] }>}
 */
export async function readPicked(entries) {
  /** @type {{ name: string, bytes: Uint8Array }[]} */
  const files = [];
  /** @type {{ source: string, reason: string }[]} */
  const refused = [];
  for (const { file, path } of entries) {
    let kind = fileKind(path);
    if (kind.reason) {
      files.push({ name: path, bytes: new Uint8Array(0) });
      continue;
    }
    if (kind.kind === 'by-content') {
      // A file without an extension: its first bytes say whether it is a zip, text, or neither.
      try {
        kind = contentKind(new Uint8Array(await file.slice(0, 1024).arrayBuffer()));
      } catch {
        kind = { reason: t('file.unreadable') };
      }
      if (kind.reason) {
        refused.push({ source: path, reason: kind.reason });
        continue;
      }
    }
    const max = kind.kind === 'zip' ? CLASS_CAPS.maxZipBytes : CLASS_CAPS.maxFileBytes;
    if (file.size > max) {
      const sizes = { size: megabytes(file.size), max: megabytes(max) };
      refused.push({ source: path, reason: t('file.tooLarge', { kind: kind.kind === 'zip' ? 'zip' : 'file', ...sizes }) });
      continue;
    }
    try {
      files.push({ name: path, bytes: new Uint8Array(await file.arrayBuffer()) });
    } catch {
      refused.push({ source: path, reason: t('file.unreadable') });
    }
  }
  return { files, refused };
}

/**
 * A picker's files, with the relative path a folder picker gives.
 * @param {FileList | null} list
 * @returns {{ file: File, path: string }[]}
 */
export const fromInput = (list) => [...(list ?? [])].map((file) => ({ file, path: file.webkitRelativePath || file.name }));

/**
 * Dropped items: files, and the files inside dropped folders (walked, up to MAX_WALKED).
 * @param {DataTransfer | null} dataTransfer
 * @returns {Promise<{ file: File, path: string }[]>}
 */
export async function fromDrop(dataTransfer) {
  if (!dataTransfer) return [];
  const roots = [...dataTransfer.items].flatMap((item) => item.webkitGetAsEntry?.() ?? []);
  if (!roots.length) return fromInput(dataTransfer.files);
  /** @type {{ file: File, path: string }[]} */
  const out = [];
  /** @type {(entry: FileSystemEntry, path: string) => Promise<void>} */
  const walk = async (entry, path) => {
    if (out.length >= MAX_WALKED) return;
    // isFile and isDirectory say which kind of entry it is; the DOM's types do not narrow on them.
    if (entry.isFile) {
      const fileEntry = /** @type {FileSystemFileEntry} */ (entry);
      /** @type {File | null} */
      const file = await new Promise((resolve, reject) => { fileEntry.file(resolve, reject); }).catch(() => null);
      if (file) out.push({ file, path: `${path}${entry.name}` });
    } else if (entry.isDirectory) {
      const reader = /** @type {FileSystemDirectoryEntry} */ (entry).createReader();
      for (;;) {
        /** @type {FileSystemEntry[]} */
        const batch = await new Promise((resolve) => { reader.readEntries(resolve, () => resolve([])); });
        if (!batch.length) break;
        for (const child of batch) await walk(child, `${path}${entry.name}/`);
      }
    }
  };
  for (const root of roots) await walk(root, '');
  return out;
}
