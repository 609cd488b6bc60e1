// @ts-check
// A composed lecture on the lecture page: its title in the page's header, then one section per
// item in its order, in place of the sections the build wrote for the lab's own lecture. A panel's
// section is the one the build writes (sectionHtml: heading, lede, citation, its place) with the
// lecturer's heading and text above it; a text item is its heading and text; a question item is a
// homework question asked of the room (questionItem.js, loaded only for a lecture that has one).
import { panelEntry, placeLayouts, sectionHtml } from '../panels/manifest.js';
import { panelText } from '../panels/panelLede.js';
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';
import { el } from '../ui/el.js';
import { fixed } from '../ui/format.js';
import { showNotice } from '../host/showNotice.js';
import { lectureTextFragment } from './lectureTextDom.js';

const t = messages('lecture', english);

/** @typedef {import('./readLecture.js').LectureItem} LectureItem */
/** @typedef {import('./readLecture.js').PanelItem} PanelItem */
/** @typedef {import('./readLecture.js').QuestionItem} QuestionItem */
/** @typedef {{ section: HTMLElement, item: PanelItem, key: string, prefix: string }} MountedPanel */
/** @typedef {{ section: HTMLElement, item: QuestionItem, number: number }} AskedQuestion */

/**
 * The lecturer's own heading and text for an item (nothing when it has neither).
 * @param {LectureItem} item
 * @param {string} key
 * @param {string} className
 */
function ownText(item, key, className) {
  const parts = [];
  if (item.heading) {
    const heading = el('h2', 'lecture-own-heading', item.heading);
    heading.id = `${key}-own`;
    parts.push(heading);
  }
  if (item.text) {
    const text = el('div', 'lecture-text');
    text.append(lectureTextFragment(item.text));
    parts.push(text);
  }
  if (!parts.length) return null;
  const box = el('div', className);
  box.append(...parts);
  return box;
}

/**
 * The manifest's section for a panel (trusted markup from this repository), keyed for this item.
 * @param {PanelItem} item  its panel one of the manifest's (readLecture keeps no other)
 * @param {string} key
 */
function panelSection(item, key) {
  const entry = panelEntry(item.panel);
  if (!entry) throw new RangeError(`No panel ${item.panel} in the manifest.`);
  const template = document.createElement('template');
  template.innerHTML = sectionHtml(entry, panelText(item.panel));
  const section = /** @type {HTMLElement} */ (template.content.firstElementChild); // sectionHtml writes one <section>
  section.id = key;
  section.dataset.item = key;
  const heading = section.querySelector('h2');
  if (heading) heading.id = `${key}-title`;
  // The place the build keeps for #<panel id> (panelPlaces.css), for every item of this panel: styles.css reads these.
  for (const [layout] of placeLayouts()) section.style.setProperty(`--place-${layout}`, `${entry.place[layout]}px`);
  const own = ownText(item, key, 'lecture-own');
  if (own) {
    section.prepend(own);
    if (item.heading) section.setAttribute('aria-labelledby', `${key}-own ${key}-title`);
  }
  return section;
}

/**
 * A section of the lecturer's text, or of a question (filled when its module arrives).
 * @param {LectureItem} item
 * @param {string} key
 * @param {string} className
 * @param {string} label
 */
function plainSection(item, key, className, label) {
  const section = el('section', `panel ${className}`);
  section.id = key;
  section.dataset.item = key;
  section.tabIndex = -1;
  const own = ownText(item, key, 'lecture-own');
  if (own) section.append(own);
  if (item.heading) section.setAttribute('aria-labelledby', `${key}-own`);
  else section.setAttribute('aria-label', label);
  return section;
}

/**
 * Shows `lecture` in `main` (the lab's own sections go), its title in the header. keys: from
 * itemKeys. Returns { sections: every item's section in order, panels: [{ section, item, key,
 * prefix }], ready: resolves once the questions are on the page (their cards, or null where they could not load) }.
 * @param {HTMLElement} main
 * @param {{ title: string, items: readonly LectureItem[] }} lecture
 * @param {{ key: string, prefix: string | null }[]} keys
 * @returns {{ sections: HTMLElement[], panels: MountedPanel[], ready: Promise<unknown> }}
 */
export function mountLecture(main, lecture, keys) {
  for (const section of main.querySelectorAll('section[data-panel]')) section.remove();
  document.title = t('pageTitle', { title: lecture.title });
  const title = document.querySelector('.site-title h1');
  if (title) title.textContent = lecture.title;
  const intro = document.querySelector('.site-title p');
  if (intro) intro.textContent = t('pageIntro');

  /** @type {HTMLElement[]} */
  const sections = [];
  /** @type {MountedPanel[]} */
  const panels = [];
  /** @type {AskedQuestion[]} */
  const questions = [];
  lecture.items.forEach((item, i) => {
    const { key, prefix } = keys[i];
    let section;
    if (item.type === 'panel') {
      if (prefix === null) throw new Error(`The panel item ${key} has no URL prefix.`); // itemKeys gives every panel one
      section = panelSection(item, key);
      panels.push({ section, item, key, prefix });
    } else if (item.type === 'question') {
      section = plainSection(item, key, 'lecture-question', t('questionLabel', { n: fixed(questions.length + 1, 0) }));
      questions.push({ section, item, number: questions.length + 1 });
    } else {
      section = plainSection(item, key, 'lecture-text-item', t('textLabel'));
    }
    sections.push(section);
  });
  main.append(...sections);
  const ready = questions.length
    ? import('./questionItem.js').then(({ askQuestions }) => askQuestions(questions), (error) => {
      for (const { section } of questions) showNotice(section, t('questionLoadFailed'), [error.message], { kind: 'error' });
      return null; // said in each question's section; the rest of the lecture goes on
    })
    : Promise.resolve();
  return { sections, panels, ready };
}
