// @ts-check
// The lecture page as it stands, as a lecture: every panel of the manifest in its order, each from
// its defaults, with its own heading and lede (the page writes those from the manifest, so the items
// carry no text of their own). A composed lecture starts from it.
import { PANELS } from '../panels/manifest.js';
import { LECTURE_KIND, LECTURE_VERSION } from './readLecture.js';
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';

const t = messages('lecture', english);

/** @returns {import('./readLecture.js').Lecture} */
export function defaultLecture() {
  return {
    kind: LECTURE_KIND, version: LECTURE_VERSION, title: t('defaultTitle'), // the lecture page's title
    items: PANELS.map(({ id }) => ({ type: 'panel', panel: id })),
  };
}
