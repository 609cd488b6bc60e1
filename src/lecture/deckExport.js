// @ts-check
// A composed lecture as a reveal.js 6 deck in one HTML file: a title slide, then one slide per item
// (deckSlides.js): a panel as a frame of the lab's embed page, the lecturer's heading and text on
// the slide, a text item as a text slide, a question with its answer on the slide below.
//
// The file carries reveal.js itself (its dist script, its CSS and the dracula theme, which fetches
// no web fonts; its colours made light for light panels), imported here as text with vite's ?raw: this module is loaded only when a deck is
// exported, so the page that offers the export does not download them. No CDN: a classroom may be
// offline. The panels come from embedUrl: the site's own embed.html for a deck used online, or
// offline/embed.html (the default) for a deck placed beside the folder dist/offline/ that
// `npm run build` writes, both opened from disk.
//
// The deck has no Content-Security-Policy of its own: it is the user's file, opened as a file or put
// on their own site, and everything it runs is inline in it (reveal.js and the lines below); the
// panels inside it are the embed page, which carries its own policy. A policy meta would have to
// allow the inline scripts by hash and the frames from wherever embedUrl points, which is the
// deck's owner's choice, not ours.
// The UMD build, which sets window.Reveal; the package's exports do not name it, so it is found by its path.
import revealJsText from '../../node_modules/reveal.js/dist/reveal.js?raw';
import revealCssText from 'reveal.js/reveal.css?raw';
import revealThemeText from 'reveal.js/theme/dracula.css?raw';
import { readLecture } from './readLecture.js';
import { escapeHtml } from '../ui/escapeHtml.js';
import { lectureSlidesHtml } from './deckSlides.js';
import { katexDeckCss } from './katexDeckCss.js';
import english from 'virtual:messages/en/lecture';
import { currentLanguage, messages } from '../i18n/messages.js';
import { LANGUAGES, languageById } from '../i18n/languages.js';
import { FRAME_GRACE_MS } from '../ui/watchPanelFrame.js';

const t = messages('lecture', english);

export const DEFAULT_EMBED_URL = 'offline/embed.html';

// Slides fill the 1280 × 720 stage as columns (reveal's display: 'flex'), so a panel's frame takes
// the height its slide's text leaves; long text scrolls in its own box.
const DECK_CSS = `
.reveal .slides section { height: 100%; box-sizing: border-box; flex-direction: column; text-align: start; padding: 0; }
.reveal .slides > section.stack { padding: 0; }
.reveal h1, .reveal h2 { text-align: start; text-transform: none; }
.reveal h2 { font-size: 1.1em; margin: 0 0 0.3em; flex: none; }
.reveal .fl-title { justify-content: center; }
.reveal .fl-title h1 { font-size: 1.8em; }
.reveal .fl-text { font-size: 0.6em; flex: 0 1 auto; min-height: 0; overflow: auto; }
.reveal .fl-text p, .reveal .fl-text ul, .reveal .fl-text ol { margin: 0 0 0.5em; }
.reveal .fl-embed { display: block; flex: 1 1 auto; min-height: 55%; width: 100%; border: 0; background: var(--r-background-color); }
.reveal .fl-short { min-height: 45%; }
.reveal .fl-kind, .reveal .fl-small { font-size: 0.5em; opacity: 0.8; margin: 0 0 0.6em; }
.reveal .fl-prompt { font-size: 0.75em; }
.reveal .fl-options, .reveal .fl-why { font-size: 0.6em; }
.reveal ol.fl-options { list-style-type: upper-alpha; }
.reveal .lecture-math-display { text-align: center; margin: 0.4em 0; }
.reveal .fl-missing { flex: 1 1 auto; min-height: 45%; box-sizing: border-box; padding: 0.6em 0.9em; font-size: 0.6em;
  border: 2px solid #ff6b7a; border-radius: 8px; background: color-mix(in srgb, var(--r-background-color) 80%, #ff6b7a 20%); }
.reveal .fl-missing p { margin: 0 0 0.5em; }
`;

// With light panels the deck is light too: dracula's colours, overridden.
const LIGHT_CSS = `
:root { --r-background: #fff; --r-background-color: #fff; --r-main-color: #1d1d1f; --r-heading-color: #5b2bb5;
  --r-link-color: #b0126f; --r-link-color-dark: #8a0e57; --r-link-color-hover: #0b6f86;
  --r-selection-background-color: #d6d0f0; --r-selection-color: #000; --r-bold-color: #8a4b00; --r-italic-color: #5a5a00;
  --r-inline-code-color: #0a7a32; --r-list-bullet-color: #0b6f86; }
`;

// The deck's own lines: reveal.js with the choices above and the keys a panel hands back
// (fresnel-lab:key, docs/deck/reveal.md), heard only from the deck's own frames (from disk
// every origin is "null", so the origin tells nothing). Linear navigation: → and Space step through
// a question's answer too, as a clicker does.
// A panel's frame holds the lab's embed page, which says so at once (fresnel-lab:loading, before its
// panel's module arrives; src/embed.js). A frame that has loaded an address and said nothing within
// FRAME_GRACE_MS holds something else: the browser's error page, where embed.html is not where the
// deck looks for it (a deck moved without its offline folder, or offline from the site). It is
// replaced by a notice in the lab's words, as the lecture page does (src/ui/watchPanelFrame.js).
// reveal.js unloads a frame by taking its src away (a load of about:blank), which is not watched.
const deckScript = (/** @type {{ title: string, why: string }} */ missing) => `
(function () {
  'use strict';
  var MISSING = ${JSON.stringify(missing)};
  var heard = [];
  var watched = document.querySelectorAll('.reveal iframe.fl-embed');
  function replace(frame) {
    var box = document.createElement('div');
    box.className = 'fl-missing';
    box.setAttribute('role', 'alert');
    var title = document.createElement('p');
    var strong = document.createElement('strong');
    strong.textContent = MISSING.title;
    title.appendChild(strong);
    var why = document.createElement('p');
    why.textContent = MISSING.why;
    box.appendChild(title);
    box.appendChild(why);
    frame.parentNode.replaceChild(box, frame);
  }
  Array.prototype.forEach.call(watched, function (frame) {
    var timer = 0;
    frame.addEventListener('load', function () {
      clearTimeout(timer);
      if (!frame.getAttribute('src') || heard.indexOf(frame) >= 0) return;
      timer = setTimeout(function () {
        if (heard.indexOf(frame) < 0 && frame.isConnected && frame.getAttribute('src')) replace(frame);
      }, ${FRAME_GRACE_MS});
    });
  });
  window.addEventListener('message', function (event) {
    var data = event.data;
    if (!data || typeof data.type !== 'string' || data.type.indexOf('fresnel-lab:') !== 0) return;
    Array.prototype.forEach.call(watched, function (frame) {
      if (frame.contentWindow === event.source && heard.indexOf(frame) < 0) heard.push(frame);
    });
  });
  var deck = new Reveal({
    hash: true, center: false, display: 'flex', width: 1280, height: 720, margin: 0.04,
    viewDistance: 2, navigationMode: 'linear', transition: 'slide'
  });
  window.deck = deck;
  deck.initialize();
  var moves = {
    PageDown: 'next', ' ': 'next', ArrowRight: 'next', ArrowDown: 'next',
    PageUp: 'prev', ArrowLeft: 'prev', ArrowUp: 'prev', Home: 'first', End: 'last'
  };
  window.addEventListener('message', function (event) {
    var data = event.data;
    if (!data || typeof data !== 'object' || data.type !== 'fresnel-lab:key' || typeof data.key !== 'string') return;
    if (!Object.prototype.hasOwnProperty.call(moves, data.key)) return;
    var frames = document.querySelectorAll('.reveal iframe');
    if (!Array.prototype.some.call(frames, function (frame) { return frame.contentWindow === event.source; })) return;
    var move = data.key === ' ' && data.shiftKey === true ? 'prev' : moves[data.key];
    if (move === 'first') deck.slide(0, 0);
    else if (move === 'last') deck.slide(deck.getHorizontalSlides().length - 1, 0);
    else deck[move]();
  });
})();
`;

/**
 * The notice that takes the place of a panel whose page did not load, for panels from `embedUrl`.
 * @param {string} embedUrl
 */
function missingWords(embedUrl) {
  const where = /^\s*https?:/i.test(embedUrl) ? 'site' : 'file';
  return { title: t('deckFrameMissing'), why: t('deckFrameMissingWhy', { where, url: embedUrl }) };
}

/** Inline script text that cannot end its element early (</script) or open a comment state (<!--). */
const scriptText = (/** @type {string} */ text) => String(text).replace(/<\/(script)/gi, '<\\/$1').replace(/<!--/g, '<\\!--');
/** Inline style text that cannot end its element early (in CSS \/ is /). */
const styleText = (/** @type {string} */ text) => String(text).replace(/<\/(style)/gi, '<\\/$1');

/**
 * The HTML text of a reveal.js deck of `lecture` (read by readLecture first; a lecture with
 * nothing usable throws).
 * @param {unknown} lecture
 * @param {object} [options]
 * @param {string} [options.embedUrl]   embed.html's address: DEFAULT_EMBED_URL for a deck beside the offline folder, or the site's own
 * @param {string} [options.revealJs]   reveal.js's UMD script (default: reveal.js 6 from the lab's build)
 * @param {string} [options.revealCss]  reveal.js's CSS and a theme (default: reveal.css and dracula.css)
 * @param {'dark' | 'light' | null} [options.theme]  the embeds' colour scheme and the deck's (default dark; null: each
 *   embed as its reader's browser has it, on a dark deck)
 * @param {boolean} [options.projector] the embeds in projector mode (larger type, thicker lines)
 * @returns {string}
 */
export function lectureDeckHtml(lecture, {
  embedUrl = DEFAULT_EMBED_URL, revealJs = revealJsText, revealCss = `${revealCssText}\n${revealThemeText}`,
  theme = 'dark', projector = false,
} = {}) {
  const scheme = typeof embedUrl === 'string' ? /^\s*([a-z][a-z0-9+.-]*):/i.exec(embedUrl) : null;
  if (typeof embedUrl !== 'string' || !embedUrl.trim() || (scheme && !['http', 'https', 'file'].includes(scheme[1].toLowerCase()))) {
    throw new TypeError('embedUrl is the address of embed.html: a relative path, or an http(s) or file URL.');
  }
  if (theme !== null && theme !== 'dark' && theme !== 'light') throw new TypeError('theme is dark, light or null.');
  const read = readLecture(lecture);
  if (!read.ok) throw new TypeError(`This is no lecture: ${read.problems.join(' ')}`);
  const { title } = read.lecture;
  // The lecture's language (the composer writes the page's) is the deck's and its panels'; a lecture
  // without one is shown in the words the deck is written in, its panels in their reader's language.
  const { lang = null } = read.lecture;
  const language = languageById(lang ?? currentLanguage()) ?? LANGUAGES[0]; // the first listed is English
  const slides = lectureSlidesHtml(read.lecture, { embedUrl, theme, projector: Boolean(projector), lang });
  return `<!doctype html>
<html lang="${escapeHtml(language.id)}" dir="${language.dir}">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="Fresnel Lab">
<title>${escapeHtml(title)}</title>
<link rel="icon" href="data:,">
<!-- No Content-Security-Policy: this deck is its owner's file and runs only what it holds inline
     (reveal.js and a few lines that move the deck); each panel is a frame of the lab's embed page,
     which has its own. Panels come from ${escapeHtml(embedUrl)}. -->
<style>${styleText(revealCss)}</style>
<style>${DECK_CSS}${theme === 'light' ? LIGHT_CSS : ''}</style>${slides.includes('class="katex"') ? `
<style>${styleText(katexDeckCss())}</style>` : ''}
</head>
<body>
<div class="reveal">
<div class="slides">
<section class="fl-title" data-title-slide>
  <h1>${escapeHtml(title)}</h1>
  <p class="fl-small">${escapeHtml(t('deckKeys'))}</p>
</section>
${slides}
</div>
</div>
<script>${scriptText(revealJs)}</script>
<script>${scriptText(deckScript(missingWords(embedUrl)))}</script>
</body>
</html>
`;
}
