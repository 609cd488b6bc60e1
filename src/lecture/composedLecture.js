// @ts-check
// A composed lecture on the lecture page, loaded only where one is given (?lecture=CODE, or the
// data element an offline lecture carries): reading it (openLecture.js, which needs the questions'
// code to check a question item), saying what it refused, and mounting its items in place of the
// lab's own sections (mountLecture.js, with the Markdown renderer and KaTeX for the lecturer's
// words). The lab's own lecture needs none of this, so its first picture does not wait for it.
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';
import { showNotice } from '../host/showNotice.js';
import { lecturePrefix } from '../panels/manifest.js';
import { itemKeys, openLecture } from './openLecture.js';
import { lectureToCode } from './lectureLink.js';
import { mountLecture } from './mountLecture.js';

const t = messages('lecture', english);

/**
 * The lecture given to the page (search: its query; carried: the data element's text or null),
 * opened in `main`: { source, title, code, composed } where composed is mountLecture's result, or
 * null when the lecture was refused (the refusal said on the page) and the lab's own is shown.
 * @param {HTMLElement} main
 * @param {URLSearchParams} search
 * @param {string | null} carried
 */
export function showComposedLecture(main, search, carried) {
  const opened = openLecture(search, carried);
  if (opened.refused) {
    showNotice(main, t('refused', { given: opened.given }), opened.problems, { kind: 'error' });
  } else {
    showNotice(main, t('partsRefused'), opened.problems);
  }
  const composed = opened.lecture ? mountLecture(main, opened.lecture, itemKeys(opened.lecture.items, lecturePrefix)) : null;
  return {
    source: opened.source,
    title: opened.lecture?.title ?? null,
    code: opened.lecture ? lectureToCode(opened.lecture) : null,
    composed,
  };
}
