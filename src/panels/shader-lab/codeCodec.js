// @ts-check
// The student's code in a link, compact: "*", the UTF-8 length in base 36, ".", then base64url
// (RFC 4648 §5) of its raw DEFLATE (RFC 1951), about half the length of the percent-encoded text
// ("*" and "." are among the few characters a query string keeps as they are). Plain text (from a
// message, or a link written by hand) reads as it is; GLSL cannot begin with "*".
// Reading comes with every page (links are read before any panel loads): fflate's inflate alone,
// about 2 KB, which stops at the end of its input and at a bad code (a smaller inflater looped for
// ever on some made-up links). Writing needs deflate, which fflate brings with the panel's module
// (useDeflate). Until then a link keeps the code as plain text, or in stored blocks when it starts
// with "*" (RFC 1951 §3.2.4), so that it reads back the same.
import { inflateSync } from 'fflate';
import { MAX_CODE } from './exerciseIds.js';

const COMPACT = /^\*([0-9a-z]{1,6})\.([A-Za-z0-9_-]*)$/;
export const MAX_BYTES = 4 * MAX_CODE * 2; // UTF-8 of the longest code the schema takes, with room: larger is refused before inflating

/** @typedef {(bytes: Uint8Array) => Iterable<number>} Deflate */

/** @type {Deflate | null} */
let deflate = null;

/**
 * deflate(bytes) → raw DEFLATE bytes (fflate's deflateSync), given by the panel's module when it loads.
 * @param {Deflate} fn
 */
export function useDeflate(fn) {
  deflate = fn;
}

/**
 * The code as the link writes it (compact, or as it is).
 * @param {string} text
 */
export function encodeCode(text) {
  if (!text || (!deflate && !text.startsWith('*'))) return text;
  const utf8 = new TextEncoder().encode(text);
  let binary = '';
  for (const b of (deflate ?? storedBlocks)(utf8)) binary += String.fromCharCode(b);
  return `*${utf8.length.toString(36)}.${btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '')}`;
}

/**
 * The text back, or null for a compact form that does not decode (a link cut short or made up).
 * @param {string} raw  from the link
 * @returns {string | null}
 */
export function decodeCode(raw) {
  if (!raw.startsWith('*')) return raw;
  const match = COMPACT.exec(raw);
  if (!match) return null;
  const length = parseInt(match[1], 36);
  if (!(length > 0 && length <= MAX_BYTES)) return null;
  try {
    const binary = atob(match[2].replace(/-/g, '+').replace(/_/g, '/'));
    // One byte of room: a stream that runs on past its stated length is refused, not cut.
    const out = inflateSync(Uint8Array.from(binary, (c) => c.charCodeAt(0)), { out: new Uint8Array(length + 1) });
    if (out.length !== length) return null;
    return new TextDecoder('utf-8', { fatal: true }).decode(out);
  } catch {
    return null;
  }
}

/**
 * Raw DEFLATE of stored blocks, no compression (RFC 1951 §3.2.4): header, LEN, NLEN, bytes.
 * @param {Uint8Array} bytes
 */
function storedBlocks(bytes) {
  /** @type {number[]} */
  const out = [];
  for (let at = 0; at === 0 || at < bytes.length; at += 0xffff) {
    const block = bytes.subarray(at, at + 0xffff);
    const last = at + 0xffff >= bytes.length ? 1 : 0;
    out.push(last, block.length & 0xff, block.length >> 8, ~block.length & 0xff, (~block.length >> 8) & 0xff, ...block);
  }
  return out;
}
