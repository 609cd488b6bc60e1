// @ts-check
// The fields of one item: a panel's heading, text and start (buildPanelStart.js), a text item's
// heading and text, a question's choice from the bank and its seed. The lecturer's text is the
// lecture's small Markdown, shown beside the field as the lecture page will show it
// (lectureTextFragment: elements and text nodes only, math by KaTeX). The composer fetches this
// module with its first item; the Markdown renderer (markdown-it and KaTeX, more than the rest of
// the composer together) comes with the first text to show, and a panel's start (the names of its
// controls, which the panel host's chunk holds) with the first panel item.
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { el } from '../ui/el.js';
import { setSubscripted } from '../ui/subscripts.js';
import { field } from '../ui/formParts.js';
import { LECTURE_CAPS } from '../lecture/readLecture.js';
import { panelEntry } from '../panels/manifest.js';
import { questionPanelTitle, questionPrompt } from './catalogue.js';
import { questionSelect } from './questionSelect.js';
import { panelTitle } from '../panels/panelText.js';

const t = messages('compose', english);

/** @type {Promise<typeof import('../lecture/lectureTextDom.js')> | null} */
let renderer = null;
/** The lecture's Markdown renderer, fetched once, when a first text is shown. */
const lectureText = () => (renderer ??= import('../lecture/lectureTextDom.js'));

/** @type {Promise<typeof import('./buildPanelStart.js')> | null} */
let panelStarts = null;

/**
 * A panel item's start and its controls (buildPanelStart.js), in a place of its own until its module is here.
 * @param {import('./composerModel.js').PanelDraft} item
 * @param {Patch} patch
 */
function panelStart(item, patch) {
  const place = el('div', 'cp-start');
  (panelStarts ??= import('./buildPanelStart.js')).then(({ buildPanelStart }) => place.replaceWith(buildPanelStart(item, { patch })));
  return place;
}

/** @typedef {import('./composerModel.js').ItemDraft} ItemDraft */
/** @typedef {(fields: import('./composerModel.js').ItemPatch) => void} Patch */

/**
 * @param {string} value
 * @param {number} max
 * @param {string} [placeholder]
 */
function textInput(value, max, placeholder) {
  const input = /** @type {HTMLInputElement} */ (el('input'));
  input.type = 'text';
  input.value = value;
  input.maxLength = max;
  if (placeholder) input.placeholder = placeholder;
  return input;
}

/**
 * A Markdown field and its preview, kept in step as the lecturer types.
 * @param {ItemDraft} item
 * @param {Patch} patch
 * @param {string} placeholder
 */
function markdownField(item, patch, placeholder) {
  const area = /** @type {HTMLTextAreaElement} */ (el('textarea', 'cp-markdown'));
  area.value = item.text;
  area.rows = 4;
  area.maxLength = LECTURE_CAPS.text;
  if (placeholder) area.placeholder = placeholder;
  const hint = el('span', 'cp-hint', t('textHint'));
  hint.id = `cp-hint-${item.key}`;
  area.setAttribute('aria-describedby', hint.id);
  const preview = el('div', 'cp-preview lecture-text');
  preview.setAttribute('aria-label', t('preview'));
  preview.setAttribute('role', 'region');
  let timer = 0;
  let shown = 0; // the latest text asked for: a render that arrives after a newer one is dropped
  const show = () => {
    const text = area.value;
    const asked = ++shown;
    if (!text.trim()) {
      preview.replaceChildren(el('p', 'cp-muted', placeholder || t('noText')));
      return;
    }
    lectureText().then(({ lectureTextFragment }) => {
      if (asked === shown) preview.replaceChildren(lectureTextFragment(text));
    });
  };
  area.addEventListener('input', () => {
    patch({ text: area.value });
    clearTimeout(timer);
    timer = setTimeout(show, 150);
  });
  show();
  const box = el('div', 'cp-text-box');
  box.append(field(t('textField'), area), hint, preview);
  return box;
}

/**
 * @param {ItemDraft} item
 * @param {Patch} patch
 * @param {string} placeholder
 */
function headingField(item, patch, placeholder) {
  const heading = textInput(item.heading, LECTURE_CAPS.heading, placeholder);
  heading.addEventListener('input', () => patch({ heading: heading.value }));
  return field(t('headingField'), heading);
}

/**
 * @param {import('./composerModel.js').QuestionDraft} item
 * @param {Patch} patch
 */
function questionFields(item, patch) {
  const select = questionSelect();
  select.value = item.question;
  const seed = textInput(item.seed, LECTURE_CAPS.seed, t('seedPlaceholder'));
  const prompt = el('p', 'cp-prompt');
  prompt.setAttribute('aria-live', 'polite');
  const where = el('p', 'cp-muted');
  const show = () => {
    setSubscripted(prompt, questionPrompt(select.value, seed.value));
    const title = questionPanelTitle(select.value);
    where.textContent = title ? t('questionWhere', { title }) : '';
  };
  select.addEventListener('change', () => { patch({ question: select.value }); show(); });
  seed.addEventListener('input', () => { patch({ seed: seed.value }); show(); });
  show();
  return [field(t('questionSelect'), select), field(t('seedField'), seed), prompt, where];
}

/**
 * The editor of one item. patch(fields): the item's fields changed.
 * @param {ItemDraft} item
 * @param {{ patch: Patch }} options
 */
export function buildItemEditor(item, { patch }) {
  const box = el('div', 'cp-item-body');
  if (item.type === 'panel') {
    const entry = panelEntry(item.panel);
    // The lecture page shows the panel's own title and paragraph always; these come above them.
    box.append(headingField(item, patch, t('panelHeadingPlaceholder', { title: entry ? panelTitle(item.panel) : item.panel })),
      markdownField(item, patch, t('panelTextPlaceholder')), panelStart(item, patch));
  } else if (item.type === 'question') {
    box.append(...questionFields(item, patch), headingField(item, patch, t('optional')),
      markdownField(item, patch, t('questionTextPlaceholder')));
  } else {
    box.append(headingField(item, patch, t('textHeadingPlaceholder')), markdownField(item, patch, ''));
  }
  return box;
}
