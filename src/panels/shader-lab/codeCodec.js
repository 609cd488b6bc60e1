// The student's code in a link, compact: "*" + base64url (RFC 4648 §5) of its raw DEFLATE
// (RFC 1951, by fflate), about half the length of the percent-encoded text ("*" is one of the few
// characters a query string keeps as it is). Plain text (from a message, or a link written by
// hand) reads as it is; GLSL cannot begin with "*".
import { deflateSync, inflateSync, strFromU8, strToU8 } from 'fflate';

const MARK = '*';
const MAX_COMPACT = 16_000; // far above any code the panel takes: refused before inflating, so a link cannot inflate to gigabytes

export function encodeCode(text) {
  const bytes = deflateSync(strToU8(text), { level: 9 });
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return MARK + btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** The text back, or null for a compact form that does not decode (a link cut short). */
export function decodeCode(raw) {
  if (!raw.startsWith(MARK)) return raw;
  if (raw.length > MAX_COMPACT) return null;
  try {
    const binary = atob(raw.slice(1).replace(/-/g, '+').replace(/_/g, '/'));
    return strFromU8(inflateSync(Uint8Array.from(binary, (c) => c.charCodeAt(0))));
  } catch {
    return null;
  }
}
