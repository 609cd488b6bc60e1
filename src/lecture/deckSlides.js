// @ts-check
// The slides of a lecture's reveal.js deck (deckExport.js), as HTML text: one <section> per item.
// Everything that comes from the lecture is escaped (lectureTextHtml.js); a panel's frame is the
// embed page with the item's start state, locks and hidden controls as embed options
// (src/host/readEmbedOptions.js, docs/deck/embed.md).
//
// At most two live WebGL contexts: a WebGL panel's frame has data-src alone, so reveal.js loads it
// when its slide is shown and unloads it (after posting 'slide:stop') when the slide is left; one
// such frame is live at a time, and a second only while the one left is being torn down. A frame
// that reveal.js preloads off screen starts drawing before any message can reach it (the embed
// mounts as soon as its module runs and pauses off screen only after a second), so only plot-only
// panels, which hold no context, get data-preload and show at once; not one whose manifest entry
// says it holds one at times (webglAtTimes: speed-accuracy's GPU read-back, while it runs).
import { mayHoldContext, panelEntry } from '../panels/manifest.js';
import { panelSchema } from '../panels/panelSchema.js';
import { embedLink } from '../host/embedLink.js';
import { KIND_NAMES, knownQuestion } from '../homework/questions.js';
import { expectedValue, questionParams, trueOption } from '../homework/gradeAnswer.js';
import { formatTolerance, formatValue } from '../homework/formatAnswer.js';
import { lectureTextHtml, subscriptedHtml } from './lectureTextHtml.js';
import { escapeHtml } from '../ui/escapeHtml.js';
import { ROOM_SEED } from './readLecture.js';
import { panelTitle } from '../panels/panelText.js';
import { labTitle } from '../host/shareLinks.js';
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';

const t = messages('lecture', english);

/** @typedef {import('./readLecture.js').PanelItem} PanelItem */
/** @typedef {import('./readLecture.js').QuestionItem} QuestionItem */
/** @typedef {import('./readLecture.js').TextItem} TextItem */
/**
 * How panel frames are written: embed.html's address, the embeds' theme and projector mode, and
 * the lecture's language.
 * @typedef {{ embedUrl: string, theme: string | null, projector: boolean, lang?: string | null }} Frame
 */

/** The seed of a question item that names none (readLecture.js): the numbers the room gets on the page. */
export const DEFAULT_QUESTION_SEED = ROOM_SEED;

/**
 * The embed page's link for panel `id` on a slide (src/host/embedLink.js), from its start `state`.
 * @param {string} base  embed.html's address, relative (offline/embed.html) or absolute
 * @param {string} id
 * @param {{ state?: import('../host/panelContract.js').Values } & import('../host/embedLink.js').EmbedOptions} [options]
 */
export function embedSource(base, id, { state = {}, ...options } = {}) {
  const schema = panelSchema(id);
  if (!schema) throw new RangeError(`No panel ${id}.`); // a lecture's panels are the manifest's (readLecture)
  return embedLink(base, { id, schema }, state, options);
}

/**
 * A panel's frame on a slide (see the note at the top on data-preload).
 * @param {string} src
 * @param {string} id
 * @param {{ short: boolean }} options
 */
function frameHtml(src, id, { short }) {
  const entry = panelEntry(id);
  if (!entry) throw new RangeError(`No panel ${id} in the manifest.`);
  const preload = mayHoldContext(entry) ? '' : ' data-preload';
  return `<iframe class="fl-embed${short ? ' fl-short' : ''}"${preload} data-src="${escapeHtml(src)}" `
    + `title="${escapeHtml(labTitle(id))}" allow="fullscreen; clipboard-write"></iframe>`;
}

// Math as KaTeX's HTML, with the deck carrying KaTeX's CSS and fonts (deckExport.js): it looks as on the site.
/** @param {string | undefined} text */
const textHtml = (text) => (text ? `\n  <div class="fl-text">${lectureTextHtml(text, { math: 'html' })}</div>` : '');

/**
 * @param {PanelItem} item
 * @param {number} n
 * @param {Frame} frame
 */
function panelSlide(item, n, frame) {
  // Without a heading of the lecturer's the slide has none: the embed shows the panel's title itself.
  const heading = item.heading ? `<h2>${escapeHtml(item.heading)}</h2>` : '';
  // fit: the panel laid out to show whole on its slide, type kept legible (src/host/fitToFrame.js).
  const { theme, projector, lang } = frame;
  const { state, lock, hide } = item;
  const src = embedSource(frame.embedUrl, item.panel, { state, lock, hide, theme, projector, fit: true, lang });
  return `<section class="fl-panel" data-item="${n}" data-item-type="panel" data-panel="${escapeHtml(item.panel)}">
  ${heading}${textHtml(item.text)}
  ${frameHtml(src, item.panel, { short: Boolean(item.text) })}
</section>`;
}

/**
 * @param {TextItem} item
 * @param {number} n
 */
function textSlide(item, n) {
  return `<section class="fl-textslide" data-item="${n}" data-item-type="text">
  ${item.heading ? `<h2>${escapeHtml(item.heading)}</h2>` : ''}${textHtml(item.text)}
</section>`;
}

/**
 * The answer in words, as the homework page says it when the lecturer reveals it.
 * @param {import('../homework/questions.js').Question} question
 * @param {unknown} params
 */
function answerHtml(question, params) {
  if (question.kind === 'choice') {
    const right = trueOption(question, params);
    return `<p class="fl-prompt"><strong>${subscriptedHtml(right.text(params))}</strong></p>\n`
      + `    <p class="fl-why">${subscriptedHtml(right.why(params))}</p>`;
  }
  const expected = expectedValue(question, params);
  // The message's own markup (<strong>), with the values escaped.
  return `<p class="fl-prompt">${t('deckAnswer', { value: escapeHtml(formatValue(question, expected)),
    tolerance: escapeHtml(formatTolerance(question)) })}</p>`;
}

/**
 * A question to the room: a vertical stack of the question (the lecturer's heading and text, the
 * prompt, the options of a choice) and below it the answer with the question's panel in the state
 * the question sets, so the deck reveals it as the homework page's lecture mode does.
 * @param {QuestionItem} item
 * @param {number} n
 * @param {Frame} frame
 */
function questionSlide(item, n, frame) {
  const question = knownQuestion(item.question);
  const params = questionParams(question, item.seed ?? DEFAULT_QUESTION_SEED);
  const optionItems = question.kind === 'choice' ? question.options(params).map((o) => `<li>${subscriptedHtml(o.text(params))}</li>`) : [];
  const options = optionItems.length ? `\n    <ol class="fl-options" type="A">${optionItems.join('')}</ol>` : '';
  const { embedUrl, theme, projector, lang } = frame;
  const src = embedSource(embedUrl, question.panel, { state: question.state(params), theme, projector, fit: true, lang });
  return `<section data-item="${n}" data-item-type="question" data-question="${escapeHtml(question.id)}">
  <section class="fl-question">
    <h2>${escapeHtml(item.heading || t('deckQuestion'))}</h2>${textHtml(item.text)}
    <p class="fl-kind">${escapeHtml(KIND_NAMES[question.kind])} · ${subscriptedHtml(panelTitle(question.panel))}</p>
    <p class="fl-prompt">${subscriptedHtml(question.prompt(params))}</p>${options}
  </section>
  <section class="fl-answer" data-item-type="answer">
    <h2>${escapeHtml(t('deckAnswerHeading'))}</h2>
    ${answerHtml(question, params)}
    ${frameHtml(src, question.panel, { short: true })}
  </section>
</section>`;
}

/**
 * Every item's slide, in order, as HTML text (the lecture as readLecture gives it).
 * @param {{ items: readonly import('./readLecture.js').LectureItem[] }} lecture
 * @param {Frame} frame  how panel frames are written
 */
export function lectureSlidesHtml(lecture, frame) {
  return lecture.items.map((item, i) => {
    if (item.type === 'panel') return panelSlide(item, i + 1, frame);
    if (item.type === 'question') return questionSlide(item, i + 1, frame);
    return textSlide(item, i + 1);
  }).join('\n');
}
