// The ways outside data enters the site's code: what the browser keeps (storage), the link, messages
// from other windows, files and fetched bodies, and the decoders of packed text. A module of src that
// uses one is a reader of outside data, which the strict type check must cover (checkStrictFiles.js),
// so that what it reads is narrowed from unknown before it is used.
// A worker's own messages, taken by `worker.onmessage` or `self.onmessage`, are not among them: they
// carry what this site's page sent its worker, or the worker's answer (a listener added with
// addEventListener('message') is counted wherever it is, a window's or a worker's). The patterns are
// read in the code without its comments and name the APIs themselves, so a module that reads through
// a helper (readTextFile, readCachedResults) is covered by the helper's module, which they find.

/** [what, pattern] for each way in. */
export const WAYS_IN = [
  ['web storage', /\b(?:localStorage|sessionStorage|indexedDB)\b/],
  ['JSON.parse', /\bJSON\.parse\b/],
  ['the link', /\bURLSearchParams\b|\blocation\.(?:search|hash|href)\b|\bdocument\.(?:URL|referrer|cookie)\b|\bwindow\.name\b/],
  ['messages from other windows', /\baddEventListener\(\s*['"]message['"]|\bwindow\.onmessage\b|\bBroadcastChannel\b/],
  ['files and pasted or dropped data', /\bFileReader\b|\bdataTransfer\b|\bclipboardData\b|\bclipboard\.read|\bshowOpenFilePicker\b/],
  ['a file or response body', /\bawait\s+[\w$.?[\]]+\.(?:text|json|arrayBuffer|bytes|blob)\(\)|\.(?:text|json|arrayBuffer|bytes|blob)\(\)\s*\.then\b/],
  ['the network', /\bfetch\s*\(|\b(?:XMLHttpRequest|WebSocket|EventSource)\b/],
  ['a decoder of packed text', /\batob\s*\(|\bDecompressionStream\b|\b(?:inflate|unzip|gunzip|unzlib|decompress)(?:Sync)?\b|\b(?:Inflate|Unzip|Gunzip|Decompress)\b/],
];

/** A module's code without its comments (a URL's // inside a string stays). */
export const codeOf = (/** @type {string} */ text) => text.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|\s)\/\/.*$/gm, '$1');

/**
 * The ways in (WAYS_IN's names) that a module's text uses, in WAYS_IN's order; [] for none.
 * @param {string} text  the module's source
 * @returns {string[]}
 */
export function waysIn(text) {
  const code = codeOf(text);
  return WAYS_IN.filter(([, pattern]) => pattern.test(code)).map(([what]) => what);
}
