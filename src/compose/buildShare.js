// @ts-check
// Sharing and carrying the composed lecture: its link (index.html?lecture=CODE) to copy or to
// present from, the lecture as a JSON file and back, and the two exports: the offline lecture (a
// .zip of the single-file lecture page with the lecture written in and the embed page its frames
// open) and a reveal.js deck. The exports are
// loaded only when asked for (a dynamic import each: reveal.js travels only with the deck's).
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { button, el } from '../ui/el.js';
import { fixed, fileSlug } from '../ui/format.js';
import { copyText, downloadBlob, downloadText } from '../host/exporters.js';
import { field, readTextFile, titledSection } from '../ui/formParts.js';
import { lectureToCode } from '../lecture/lectureLink.js';
import { readLecture } from '../lecture/readLecture.js';
import { loadTheme } from '../ui/theme.js';

const t = messages('compose', english);

/**
 * The lecture page's address for a lecture, with the lecture's language (lang=), which the page
 * needs before it reads the lecture: every word it writes is in that language.
 * @param {import('../lecture/readLecture.js').Lecture} lecture
 */
export function lectureAddress(lecture) {
  const url = new URL('./index.html', window.location.href);
  url.search = '';
  url.hash = '';
  url.searchParams.set('lecture', lectureToCode(lecture));
  if (lecture.lang) url.searchParams.set('lang', lecture.lang);
  return url.toString();
}

/** @typedef {import('../lecture/readLecture.js').Lecture} Lecture */

/**
 * onOpen(lecture, problems, fileName): a lecture file was read. Returns { element, update({ lecture, problems }) }.
 * @param {{ onOpen: (lecture: Lecture, problems: string[], fileName: string) => void }} options
 */
export function buildShare({ onOpen }) {
  const { section, heading } = titledSection('cp-share', 'cp-share-title', t('shareHeading'));
  const problems = el('div', 'cp-problems');
  problems.setAttribute('role', 'status');
  const message = el('div', 'cp-message');
  message.setAttribute('role', 'status');
  message.setAttribute('aria-live', 'polite');
  /** @type {(text: string, kind?: 'ok' | 'problem') => void} */
  const say = (text, kind = 'ok') => message.replaceChildren(el('p', kind === 'ok' ? 'cp-ok' : 'cp-problem', text));

  const link = /** @type {HTMLInputElement} */ (el('input'));
  link.type = 'text';
  link.readOnly = true;
  const size = el('span', 'cp-muted');
  const copy = button(t('copyLink'));
  const present = /** @type {HTMLAnchorElement} */ (el('a', 'cp-present', t('present')));
  present.target = '_blank';
  present.rel = 'noopener';
  const save = button(t('saveJson'));
  const file = /** @type {HTMLInputElement} */ (el('input'));
  file.type = 'file';
  file.accept = '.json,application/json';
  const offline = button(t('saveOffline'));
  const deck = button(t('saveDeck'));
  // The deck's panels: this site's embed page (a deck used online), or offline/embed.html beside
  // the deck (a deck put next to the lab's offline folder, opened from disk or a USB stick).
  const deckPanels = /** @type {HTMLSelectElement} */ (el('select'));
  deckPanels.add(new Option(t('deckFromSite'), 'site'));
  deckPanels.add(new Option(t('deckFromOffline'), 'offline'));

  const linkRow = el('div', 'cp-row');
  linkRow.append(field(t('linkField'), link, 'cp-link'), copy, present);
  const fileRow = el('div', 'cp-row');
  fileRow.append(save, field(t('openFile'), file));
  const exportRow = el('div', 'cp-row');
  exportRow.append(offline, deck, field(t('deckPanels'), deckPanels));
  section.append(heading, problems, linkRow, size, fileRow, exportRow, message);

  /** @type {Lecture | null} */
  let current = null;
  /** @param {{ lecture: Lecture | null, problems: string[] }} read */
  function update({ lecture, problems: found }) {
    current = lecture && lecture.items.length ? lecture : null;
    const lines = lecture && !lecture.items.length ? [t('addOne')] : found;
    problems.replaceChildren(...(lines.length
      ? [el('p', null, t('leftOut')), ...lines.map((p) => el('p', 'cp-problem', p))]
      : []));
    link.value = current ? lectureAddress(current) : '';
    size.textContent = current ? t('linkLength', { count: link.value.length, n: fixed(link.value.length, 0) }) : '';
    for (const control of [copy, save, offline, deck]) control.disabled = !current;
    if (current) present.href = link.value;
    else present.removeAttribute('href');
    present.setAttribute('aria-disabled', String(!current));
  }

  copy.addEventListener('click', async () => {
    link.select();
    say((await copyText(link.value)) ? t('linkCopied') : t('copyRefused'));
  });
  save.addEventListener('click', () => {
    if (current) downloadText(`${fileSlug(current.title)}.lecture.json`, `${JSON.stringify(current, null, 2)}\n`, 'application/json');
  });
  file.addEventListener('change', async () => {
    const chosen = file.files?.[0];
    if (!chosen) return;
    const picked = await readTextFile(chosen);
    /** @type {import('../lecture/readLecture.js').ReadLecture} */
    let read = { ok: false, problems: picked.problems ?? [] };
    if (picked.ok) {
      try {
        read = readLecture(JSON.parse(picked.text));
      } catch {
        read = { ok: false, problems: [t('notJson')] };
      }
    }
    file.value = '';
    if (read.ok) onOpen(read.lecture, read.problems, chosen.name);
    else {
      message.replaceChildren(el('p', 'cp-problem', t('notLecture', { file: chosen.name })),
        ...read.problems.map((p) => el('p', 'cp-problem', p)));
    }
  });

  offline.addEventListener('click', async () => {
    if (!current) return;
    const lecture = current;
    say(t('offlineMaking'));
    /** @type {(name: string) => Promise<string | null>} The text of a file of the built offline folder beside this page, or null. */
    const read = async (name) => {
      try {
        const response = await fetch(`offline/${name}`);
        return response.ok ? await response.text() : null;
      } catch {
        return null;
      }
    };
    const [index, embed, favicon] = await Promise.all(['index.html', 'embed.html', 'favicon.svg'].map(read));
    if (index === null || embed === null) {
      say(window.location.protocol === 'file:' ? t('offlineFromDisk') : t('offlineMissing'), 'problem');
      return;
    }
    // The single-file pages carry their scripts inline; a page that loads script files is not one
    // (the development server answers any address with the lecture page's sources).
    if ([index, embed].some((page) => /<script[^>]+\bsrc=/i.test(page))) {
      say(t('offlineNotSingle'), 'problem');
      return;
    }
    try {
      const { offlineLectureZip } = await import('../lecture/offlineExport.js');
      const folder = fileSlug(lecture.title);
      const zip = await offlineLectureZip({ index, embed, favicon: favicon ?? undefined }, lecture, folder);
      downloadBlob(`${folder}.zip`, new Blob([zip], { type: 'application/zip' }));
      say(t('offlineSaved', { folder }));
    } catch (error) {
      say(error instanceof Error ? error.message : String(error), 'problem');
    }
  });

  deck.addEventListener('click', async () => {
    if (!current) return;
    const lecture = current;
    try {
      const { lectureDeckHtml } = await import('../lecture/deckExport.js');
      const { scheme, projector } = loadTheme();
      const embedUrl = deckPanels.value === 'site' ? new URL('./embed.html', window.location.href).toString() : 'offline/embed.html';
      const options = { embedUrl, theme: scheme, projector };
      downloadText(`${fileSlug(lecture.title)}.deck.html`, lectureDeckHtml(lecture, options), 'text/html');
      say(t(deckPanels.value === 'site' ? 'deckSavedSite' : 'deckSavedOffline'));
    } catch (error) {
      say(error instanceof Error ? error.message : String(error), 'problem');
    }
  });

  return { element: section, update, say };
}
