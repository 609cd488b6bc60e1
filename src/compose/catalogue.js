// @ts-check
// What the composer offers: every panel of the manifest by its title and lede as plain text (the
// manifest's ledes are HTML written for the lecture page; the composer shows them as text only),
// and every question of the homework bank by its prompt, with the numbers the room gets (ROOM_SEED) or its seed gives.
import { PANELS, panelEntry } from '../panels/manifest.js';
import { panelTitle } from '../panels/panelText.js';
import { panelLede } from '../panels/panelLede.js';
import { KIND_NAMES, QUESTIONS } from '../homework/questions.js';
import { questionParams } from '../homework/gradeAnswer.js';
import { ROOM_SEED } from '../lecture/readLecture.js';

/** @type {Readonly<Record<string, string>>} */
const ENTITIES = { amp: '&', lt: '<', gt: '>', quot: '"', apos: "'", nbsp: '\u00a0' };

/**
 * The text of an HTML fragment: tags dropped (a <sub> kept as _ so the page can subscript it), entities read, spaces collapsed.
 * @param {unknown} html
 */
export function plainText(html) {
  return String(html)
    .replace(/<sub>/gi, '_').replace(/<[^>]*>/g, '')
    .replace(/&(#x[0-9a-f]+|#\d+|[a-z]+);/gi, (whole, /** @type {string} */ name) => {
      if (name[0] === '#') {
        const code = name[1].toLowerCase() === 'x' ? parseInt(name.slice(2), 16) : parseInt(name.slice(1), 10);
        return code > 0 && code <= 0x10ffff ? String.fromCodePoint(code) : whole;
      }
      return Object.hasOwn(ENTITIES, name.toLowerCase()) ? ENTITIES[name.toLowerCase()] : whole;
    })
    .replace(/\s+/g, ' ').trim();
}

/**
 * The first sentences of a text, up to about `max` characters, cut at a sentence's end where one is near.
 * @param {string} text
 */
export function shortText(text, max = 220) {
  if (text.length <= max) return text;
  const cut = text.slice(0, max);
  const end = Math.max(cut.lastIndexOf('. '), cut.lastIndexOf('? '));
  return end > max / 3 ? cut.slice(0, end + 1) : `${cut.slice(0, cut.lastIndexOf(' ')).trimEnd()}…`;
}

/** The panels, in lecture order: { id, title, lede } (lede: plain text, shortened). */
export function panelCatalogue() {
  return PANELS.map((p) => ({ id: p.id, title: panelTitle(p.id), lede: shortText(plainText(panelLede(p.id))) }));
}

/** The questions, grouped by panel in lecture order: [{ panel, title, questions: [{ id, kind, prompt }] }]. */
export function questionCatalogue() {
  return PANELS.map((p) => ({
    panel: p.id,
    title: panelTitle(p.id),
    questions: QUESTIONS.filter((q) => q.panel === p.id)
      .map((q) => ({ id: q.id, kind: KIND_NAMES[q.kind], prompt: q.prompt(questionParams(q, ROOM_SEED)) })),
  })).filter((group) => group.questions.length);
}

/**
 * A question's prompt with the numbers a seed gives (with none, the room's: ROOM_SEED, as the page and the deck).
 * @param {string} id
 */
export function questionPrompt(id, seed = '') {
  const q = QUESTIONS.find((question) => question.id === id);
  return q ? q.prompt(questionParams(q, seed.trim() || ROOM_SEED)) : '';
}

/** The title of a question's panel. */
export const questionPanelTitle = (/** @type {string} */ id) => {
  const panel = QUESTIONS.find((q) => q.id === id)?.panel ?? '';
  return panelEntry(panel) ? panelTitle(panel) : '';
};
