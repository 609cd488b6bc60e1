// A note beside a panel where the lab departs from the lecture: the panel teaches the lecture as it
// stands, and this says in a sentence where the physics differs, with the published source
// (DESIGN.md, "Say where the lecture is loose"). Its text is set as text, so numbers computed by the
// panel can be woven in and nothing in it becomes markup.
import english from 'virtual:messages/en/ui';
import { messages } from '../i18n/messages.js';
import { el } from './el.js';

const t = messages('ui', english);

/**
 * host: where the note goes (appended). Returns { element, set(text, source) }: the sentence and
 * the source it rests on (a citation, shown after it).
 */
export function lectureNote(host) {
  const element = el('aside', 'lecture-note');
  element.setAttribute('aria-label', t('noteRegion'));
  const label = el('strong', 'lecture-note-label', `${t('noteLabel')} `);
  const text = el('span', 'lecture-note-text');
  const source = el('cite', 'lecture-note-source');
  element.append(label, text, ' ', source);
  host.append(element);
  return {
    element,
    set(sentence, cited) {
      text.textContent = sentence;
      source.textContent = `(${cited})`;
    },
  };
}
