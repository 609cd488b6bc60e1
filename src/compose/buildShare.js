// Sharing and carrying the composed lecture: its link (index.html?lecture=CODE) to copy or to
// present from, the lecture as a JSON file and back, and the two exports: the offline lecture (a
// .zip of the single-file lecture page with the lecture written in and the embed page its frames
// open) and a reveal.js deck. The exports are
// loaded only when asked for (a dynamic import each: reveal.js travels only with the deck's).
import { button, el } from '../ui/el.js';
import { fixed, fileSlug } from '../ui/format.js';
import { copyText, downloadBlob, downloadText } from '../host/exporters.js';
import { field, readTextFile, titledSection } from '../homework/page/formParts.js';
import { lectureToCode } from '../lecture/lectureLink.js';
import { readLecture } from '../lecture/readLecture.js';
import { loadTheme } from '../ui/theme.js';

/** The lecture page's address for a lecture. */
export function lectureAddress(lecture) {
  const url = new URL('./index.html', window.location.href);
  url.search = '';
  url.hash = '';
  url.searchParams.set('lecture', lectureToCode(lecture));
  return url.toString();
}

/** onOpen(lecture, problems, fileName): a lecture file was read. Returns { element, update({ lecture, problems }) }. */
export function buildShare({ onOpen }) {
  const { section, heading } = titledSection('cp-share', 'cp-share-title', 'Share, present, carry');
  const problems = el('div', 'cp-problems');
  problems.setAttribute('role', 'status');
  const message = el('div', 'cp-message');
  message.setAttribute('role', 'status');
  message.setAttribute('aria-live', 'polite');
  const say = (text, kind = 'ok') => message.replaceChildren(el('p', kind === 'ok' ? 'cp-ok' : 'cp-problem', text));

  const link = /** @type {HTMLInputElement} */ (el('input'));
  link.type = 'text';
  link.readOnly = true;
  const size = el('span', 'cp-muted');
  const copy = button('Copy the link');
  const present = /** @type {HTMLAnchorElement} */ (el('a', 'cp-present', 'Present'));
  present.target = '_blank';
  present.rel = 'noopener';
  const save = button('Download the lecture (JSON)');
  const file = /** @type {HTMLInputElement} */ (el('input'));
  file.type = 'file';
  file.accept = '.json,application/json';
  const offline = button('Download offline lecture (.zip: the lecture and its panels’ page)');
  const deck = button('Download reveal.js deck');
  // The deck's panels: this site's embed page (a deck used online), or offline/embed.html beside
  // the deck (a deck put next to the lab's offline folder, opened from disk or a USB stick).
  const deckPanels = /** @type {HTMLSelectElement} */ (el('select'));
  deckPanels.add(new Option('from this site (the deck needs the network)', 'site'));
  deckPanels.add(new Option('from offline/embed.html beside the deck (a USB stick)', 'offline'));

  const linkRow = el('div', 'cp-row');
  linkRow.append(field('Lecture link', link, 'hw-field cp-link'), copy, present);
  const fileRow = el('div', 'cp-row');
  fileRow.append(save, field('Open a lecture file', file));
  const exportRow = el('div', 'cp-row');
  exportRow.append(offline, deck, field('The deck’s panels come', deckPanels));
  section.append(heading, problems, linkRow, size, fileRow, exportRow, message);

  let current = null;
  function update({ lecture, problems: found }) {
    current = lecture && lecture.items.length ? lecture : null;
    const lines = lecture && !lecture.items.length ? ['Add at least one item.'] : found;
    problems.replaceChildren(...(lines.length
      ? [el('p', null, 'What the lecture page would leave out:'), ...lines.map((p) => el('p', 'cp-problem', p))]
      : []));
    link.value = current ? lectureAddress(current) : '';
    size.textContent = current ? `The link is ${fixed(link.value.length, 0)} characters long.` : '';
    for (const control of [copy, save, offline, deck]) control.disabled = !current;
    if (current) present.href = link.value;
    else present.removeAttribute('href');
    present.setAttribute('aria-disabled', String(!current));
  }

  copy.addEventListener('click', async () => {
    link.select();
    say((await copyText(link.value)) ? 'The link is copied.' : 'Copying was refused here: the link is selected, press Ctrl+C (⌘C).');
  });
  save.addEventListener('click', () => {
    if (current) downloadText(`${fileSlug(current.title)}.lecture.json`, `${JSON.stringify(current, null, 2)}\n`, 'application/json');
  });
  file.addEventListener('change', async () => {
    const chosen = file.files?.[0];
    if (!chosen) return;
    const picked = await readTextFile(chosen);
    let read = picked;
    if (picked.ok) {
      try {
        read = readLecture(JSON.parse(picked.text));
      } catch {
        read = { ok: false, problems: ['This file is not JSON.'] };
      }
    }
    file.value = '';
    if (read.ok) onOpen(read.lecture, read.problems, chosen.name);
    else {
      message.replaceChildren(el('p', 'cp-problem', `${chosen.name} is not a lecture the lab can open:`),
        ...read.problems.map((p) => el('p', 'cp-problem', p)));
    }
  });

  offline.addEventListener('click', async () => {
    if (!current) return;
    const lecture = current;
    say('Making the offline lecture…');
    /** The text of a file of the built offline folder beside this page, or null. */
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
      return say(window.location.protocol === 'file:'
        ? 'This page was opened from disk, where it may not read the offline folder beside it: open the composer from the lab’s web server.'
        : 'The single-file pages (offline/index.html and offline/embed.html beside this page) could not be read: they are made by '
          + 'npm run build, so open the composer from the built site.', 'problem');
    }
    // The single-file pages carry their scripts inline; a page that loads script files is not one
    // (the development server answers any address with the lecture page's sources).
    if ([index, embed].some((page) => /<script[^>]+\bsrc=/i.test(page))) {
      return say('offline/index.html here is not the single-file lecture page (the development server has none): '
        + 'build the site (npm run build) and open the composer from it.', 'problem');
    }
    try {
      const { offlineLectureZip } = await import('../lecture/offlineExport.js');
      const folder = fileSlug(lecture.title);
      const zip = await offlineLectureZip({ index, embed, favicon: favicon ?? undefined }, lecture, folder);
      downloadBlob(`${folder}.zip`, new Blob([zip], { type: 'application/zip' }));
      say(`The offline lecture is saved as ${folder}.zip: unpack it anywhere (a USB stick too) and open ${folder}/index.html, `
        + 'with no server. embed.html beside it shows the panels of its questions and what Copy embed code links to.');
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
      say(deckPanels.value === 'site' ? 'The reveal.js deck is saved: one slide per item, the panels as embeds of this site.'
        : 'The reveal.js deck is saved: put it next to the lab’s offline folder (dist/offline from npm run build); it opens from disk.');
    } catch (error) {
      say(error instanceof Error ? error.message : String(error), 'problem');
    }
  });

  return { element: section, update, say };
}
