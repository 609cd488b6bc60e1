// The Content-Security-Policy every built page carries as a <meta> (vite.config.js adds it at build
// time only: the dev server injects inline scripts of its own). A host that sends no header still
// gets it; one that sends a header gets both, and the stricter wins for each directive.
import { createHash } from 'node:crypto';

/**
 * The policy for a page, and why each source is there. Its inline <script> and <style> texts are
 * allowed by their SHA-256 and nothing else inline. A served page loads its files from its own
 * origin; a single-file page (dist/offline) loads none: its fonts are data: URLs, its workers start
 * from blob: URLs.
 * @param {{ singleFile?: boolean, scripts?: string[], styles?: string[] }} page
 * @returns {string}
 */
export function contentSecurityPolicy({ singleFile = false, scripts = [], styles = [] }) {
  const own = singleFile ? [] : ["'self'"];
  const directives = {
    'default-src': ["'none'"],
    'script-src': [...own, ...scripts.map(hashSource)],
    'style-src': [...own, ...styles.map(hashSource)],
    // Exports and posters redraw pictures decoded from data: URLs; the icon is a file beside the page.
    'img-src': ["'self'", 'data:'],
    // KaTeX's fonts are files on a served page; lil-gui's icon font is a data: URL in its CSS.
    'font-src': singleFile ? ['data:'] : ["'self'", 'data:'],
    'worker-src': singleFile ? ['blob:'] : ["'self'"],
    // The homework page fetches the offline pages next to it to make a SCORM package, the composer
    // the offline lecture page to export a lecture as one file.
    'connect-src': singleFile ? ["'none'"] : ["'self'"],
    // The homework page and the composer show panels in frames of the embed page beside them.
    'frame-src': ["'self'"],
    'base-uri': ["'none'"],
    'form-action': ["'none'"],
  };
  return Object.entries(directives)
    .map(([name, sources]) => `${name} ${sources.length ? sources.join(' ') : "'none'"}`).join('; ');
}

/** The CSP source that allows exactly this inline text. */
export function hashSource(text) {
  return `'sha256-${createHash('sha256').update(text, 'utf8').digest('base64')}'`;
}

/**
 * The texts of a page's inline scripts and styles, as the browser hashes them (a script of a
 * non-JavaScript type, such as the sheet's JSON data block, is data and needs no source).
 * @returns {{ scripts: string[], styles: string[] }}
 */
export function inlineTexts(html) {
  const scripts = [...html.matchAll(/<script(?![^>]*\bsrc=)([^>]*)>([\s\S]*?)<\/script>/gi)]
    .filter(([, attributes]) => !/\btype=["']?(?!module\b|text\/javascript\b)[\w/+.-]+/i.test(attributes))
    .map(([, , text]) => text);
  const styles = [...html.matchAll(/<style\b[^>]*>([\s\S]*?)<\/style>/gi)].map(([, text]) => text);
  return { scripts, styles };
}

/**
 * The page with its policy meta at the top of <head> (after its charset, if that comes first): a
 * meta policy governs only what comes after it. Throws where the page has no <head> or already has
 * a policy meta (two would both apply).
 */
export function withPolicyMeta(html, policy) {
  if (/http-equiv=["']?content-security-policy/i.test(html)) throw new Error('the page already has a Content-Security-Policy meta');
  const head = /<head[^>]*>(\s*<meta charset[^>]*>)?/i.exec(html);
  if (!head) throw new Error('the page has no <head>');
  const at = head.index + head[0].length;
  const meta = `\n  <meta http-equiv="Content-Security-Policy" content="${policy}">`;
  return `${html.slice(0, at)}${meta}${html.slice(at)}`;
}
