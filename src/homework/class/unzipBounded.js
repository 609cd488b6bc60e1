// @ts-check
// A zip from outside, opened without trusting its headers: an LMS's "download all submissions", or
// a zip a student handed in (the LMS keeps it as it came). Every decision is made from the zip's
// directory before anything is unpacked: too many entries, a name that is not read, a method or
// encryption this reader does not know, a claimed size over its cap or over what is left of the
// class's total. What is unpacked is then held to its claim.
//
// Why not fflate's unzipSync with a filter: it inflates each entry into a buffer of the claimed size,
// which bounds memory, but a stream that expands past its claim runs on to its end with its output
// dropped, and nothing tells it apart from an honest entry (a 200 KB stream claiming a few bytes
// takes about a second; a 20 MB one, a minute and a half). Here the deflate stream goes through
// fflate's Inflate a few kilobytes at a time and stops as soon as it passes its claim, so no entry
// costs more than its claim plus one step's output (4 MB); the CRC-32 of what came out is checked.
import { Inflate, inflateSync, strFromU8 } from 'fflate';
import { megabytes } from './classCaps.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

const END = 0x06054b50; // end of central directory
const END64 = 0x06064b50;
const END64_LOCATOR = 0x07064b50;
const CENTRAL = 0x02014b50;
const LOCAL = 0x04034b50;
const STEP = 4096; // compressed bytes per push: at most about 4 MB of output (deflate's limit is 1032:1)

// Little-endian integers at offset o; past the end a byte reads as undefined, which | and << take as 0.
/** @type {(b: Uint8Array, o: number) => number} */
const u16 = (b, o) => b[o] | (b[o + 1] << 8);
/** @type {(b: Uint8Array, o: number) => number} */
const u32 = (b, o) => (b[o] | (b[o + 1] << 8) | (b[o + 2] << 16) | (b[o + 3] << 24)) >>> 0;
/** @type {(b: Uint8Array, o: number) => number} */
const u64 = (b, o) => u32(b, o) + u32(b, o + 4) * 2 ** 32;

/**
 * @typedef {{ entries: number, bytes: number }} ZipBudget What is left of the class's caps (entries
 *   and unpacked bytes), shared by a zip and the zips inside it; unzipBounded spends it.
 * @typedef {{ name: string, bytes: Uint8Array }} ZipFile A file unpacked, named by its path in the zip.
 * @typedef {{ source: string, reason: string }} Refusal
 * @typedef {{ bytes: Uint8Array, reason?: undefined } | { reason: string, bytes?: undefined }} Unpacked An entry's data, or
 *   why it was refused.
 */

/** @type {Int32Array | null} */
let crcTable = null;
/**
 * CRC-32 (ISO 3309, as zip uses): a damaged entry, or one whose stream ended early, fails it.
 * @param {Uint8Array} bytes
 */
function crc32(bytes) {
  if (!crcTable) {
    crcTable = new Int32Array(256);
    for (let n = 0; n < 256; n += 1) {
      let c = n;
      for (let k = 0; k < 8; k += 1) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c;
    }
  }
  const table = crcTable;
  let c = -1;
  for (let i = 0; i < bytes.length; i += 1) c = table[(c ^ bytes[i]) & 255] ^ (c >>> 8);
  return (c ^ -1) >>> 0;
}

/**
 * The end-of-directory record (zip64 where the plain one overflows): { count, offset } or null.
 * @param {Uint8Array} b
 */
function findDirectory(b) {
  for (let e = b.length - 22; e >= Math.max(0, b.length - 22 - 0xffff); e -= 1) {
    if (u32(b, e) !== END) continue;
    let count = u16(b, e + 10);
    let offset = u32(b, e + 16);
    if ((count === 0xffff || offset === 0xffffffff) && e >= 20 && u32(b, e - 20) === END64_LOCATOR) {
      const at = u64(b, e - 12);
      if (at + 56 <= b.length && u32(b, at) === END64) {
        count = u64(b, at + 32);
        offset = u64(b, at + 48);
      }
    }
    return { count, offset };
  }
  return null;
}

/**
 * An entry's name: UTF-8 where flagged or where it reads as UTF-8 (many tools never flag it), else Latin-1.
 * @param {Uint8Array} bytes
 * @param {boolean} utf8Flag
 */
function entryName(bytes, utf8Flag) {
  let name;
  try {
    name = new TextDecoder('utf-8', { fatal: !utf8Flag }).decode(bytes);
  } catch {
    name = strFromU8(bytes, true);
  }
  return name.replace(/\\/g, '/').replace(/^(\.?\/)+/, '');
}

/**
 * The sizes and local offset of a central entry, zip64 extra field read where a field overflows.
 * @param {Uint8Array} b
 * @param {number} p
 * @param {number} nameLength
 * @param {number} extraLength
 */
function entrySizes(b, p, nameLength, extraLength) {
  let size = u32(b, p + 20);
  let claimed = u32(b, p + 24);
  let local = u32(b, p + 42);
  if (claimed === 0xffffffff || size === 0xffffffff || local === 0xffffffff) {
    const end = p + 46 + nameLength + extraLength;
    for (let x = p + 46 + nameLength; x + 4 <= end;) {
      const id = u16(b, x);
      const length = u16(b, x + 2);
      if (id === 1) {
        let f = x + 4;
        if (claimed === 0xffffffff && f + 8 <= end) claimed = u64(b, f), f += 8;
        if (size === 0xffffffff && f + 8 <= end) size = u64(b, f), f += 8;
        if (local === 0xffffffff && f + 8 <= end) local = u64(b, f);
        break;
      }
      x += 4 + length;
    }
  }
  return { size, claimed, local };
}

const t = messages('class', english);
/** @type {(claimed: number) => Unpacked} */
const BOMB = (claimed) => ({ reason: t('zip.bomb', { claimed }) });
/** @type {() => Unpacked} */
const DAMAGED = () => ({ reason: t('zip.damagedData') });
/** @type {(length: number, claimed: number) => Unpacked} */
const WRONG_LENGTH = (length, claimed) => ({ reason: t('zip.wrongLength', { length, claimed }) });

/**
 * Inflates `input` to exactly `claimed` bytes, stopping as soon as it would pass them.
 * @param {Uint8Array} input
 * @param {number} claimed
 * @returns {Unpacked}
 */
function inflateBounded(input, claimed) {
  if (input.length <= STEP) {
    // One step's input can only make one step's output, so it is inflated at once into a buffer one
    // byte longer than its claim: a stream that fills that byte says more than it claimed. (A hand-in
    // is a few kilobytes; the streaming inflater's buffers cost more than the inflating.)
    let out;
    try {
      out = inflateSync(input, { out: new Uint8Array(claimed + 1) });
    } catch {
      return DAMAGED();
    }
    if (out.length > claimed) return BOMB(claimed);
    return out.length === claimed ? { bytes: out.subarray(0, claimed) } : WRONG_LENGTH(out.length, claimed);
  }
  const out = new Uint8Array(claimed);
  let length = 0;
  let over = false;
  const inflater = new Inflate((chunk) => {
    if (over || length + chunk.length > claimed) {
      over = true;
      return;
    }
    out.set(chunk, length);
    length += chunk.length;
  });
  try {
    if (input.length === 0) inflater.push(new Uint8Array(0), true);
    for (let at = 0; at < input.length && !over; at += STEP) inflater.push(input.subarray(at, at + STEP), at + STEP >= input.length);
  } catch {
    if (!over) return DAMAGED();
  }
  if (over) return BOMB(claimed);
  if (length !== claimed) return WRONG_LENGTH(length, claimed);
  return { bytes: out };
}

/**
 * The files of a zip that `admit` lets in, each held to its claimed size.
 * name: the zip's own name (its entries are named `${name}/${path}`); admit(path, claimedBytes):
 * null to unpack that entry, or the reason it is refused (decided before unpacking); budget: what is
 * left of the class's entries and bytes (spent here); maxEntries: the most entries a zip's directory
 * may list. Never throws on any bytes.
 * @param {Uint8Array} bytes
 * @param {{ name: string, admit: (path: string, claimed: number) => string | null, budget: ZipBudget, maxEntries: number }} options
 * @returns {{ files: ZipFile[], refused: Refusal[] }}
 */
export function unzipBounded(bytes, { name, admit, budget, maxEntries }) {
  /** @type {ZipFile[]} */
  const files = [];
  /** @type {Refusal[]} */
  const refused = [];
  /** @type {(source: string, reason: string) => void} */
  const refuse = (source, reason) => { refused.push({ source, reason }); };
  const b = bytes;
  const directory = findDirectory(b);
  if (!directory) {
    refuse(name, t('zip.noDirectory'));
    return { files, refused };
  }
  const { count } = directory;
  if (count > maxEntries) {
    refuse(name, t('zip.tooManyEntries', { count, max: maxEntries }));
    return { files, refused };
  }
  let p = directory.offset;
  for (let i = 0; i < count; i += 1) {
    if (p + 46 > b.length || u32(b, p) !== CENTRAL) {
      refuse(name, t('zip.directoryBroken', { read: i, count }));
      break;
    }
    const flags = u16(b, p + 8);
    const method = u16(b, p + 10);
    const crc = u32(b, p + 16);
    const nameLength = u16(b, p + 28);
    const extraLength = u16(b, p + 30);
    const commentLength = u16(b, p + 32);
    const path = entryName(b.subarray(p + 46, Math.min(b.length, p + 46 + nameLength)), (flags & 0x800) !== 0);
    const { size, claimed, local } = entrySizes(b, p, nameLength, extraLength);
    p += 46 + nameLength + extraLength + commentLength;
    if (path === '' || path.endsWith('/')) continue; // a folder: its files are entries of their own
    const source = `${name}/${path}`;
    if (budget.entries <= 0) {
      refuse(source, t('zip.entriesFull'));
      continue;
    }
    budget.entries -= 1;
    const refusal = admit(path, claimed);
    if (refusal) refuse(source, refusal);
    else if (flags & 1) refuse(source, t('zip.encrypted'));
    else if (method !== 0 && method !== 8) refuse(source, t('zip.method', { method }));
    else if (claimed > budget.bytes) refuse(source, t('zip.bytesFull', { size: megabytes(claimed), left: megabytes(budget.bytes) }));
    else {
      const read = readEntry(b, { local, size, claimed, method, crc });
      if (!read.bytes) refuse(source, read.reason);
      else {
        budget.bytes -= claimed;
        files.push({ name: source, bytes: read.bytes });
      }
    }
  }
  return { files, refused };
}

/**
 * One entry's data, from its local header.
 * @param {Uint8Array} b
 * @param {{ local: number, size: number, claimed: number, method: number, crc: number }} entry
 * @returns {Unpacked}
 */
function readEntry(b, { local, size, claimed, method, crc }) {
  if (local + 30 > b.length || u32(b, local) !== LOCAL) return { reason: t('zip.dataMissing') };
  const start = local + 30 + u16(b, local + 26) + u16(b, local + 28);
  if (start + size > b.length) return { reason: t('zip.dataCut') };
  const data = b.subarray(start, start + size);
  /** @type {Unpacked} */
  let read;
  if (method === 0) read = size === claimed ? { bytes: data.slice() } : { reason: t('zip.storedLength', { size, claimed }) };
  else read = inflateBounded(data, claimed);
  if (read.bytes && crc32(read.bytes) !== crc) return { reason: t('zip.checksum') };
  return read;
}
