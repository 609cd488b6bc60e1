// @ts-check
// A question of a composed lecture, asked of the room as the homework page's lecture mode asks it:
// homework's question card (buildQuestionCard, with its styles) judges nothing until the lecturer
// reveals it; a prediction's panel appears with the truth. Loaded only by a lecture that has a question.
import { knownQuestion } from '../homework/questions.js';
import { questionParams } from '../homework/gradeAnswer.js';
import { buildQuestionCard } from '../homework/card/buildQuestionCard.js';
import { button } from '../ui/el.js';
import { ROOM_SEED } from './readLecture.js';
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';

const t = messages('lecture', english);

/**
 * Each { section, item, number } gets its card and a "Reveal the answer" button. Returns the cards.
 * @param {import('./mountLecture.js').AskedQuestion[]} questions
 */
export function askQuestions(questions) {
  /** @type {Set<HTMLIFrameElement>} the panels' frames, each fitted to the height it reports */
  const frames = new Set();
  const cards = questions.map(({ section, item, number }) => {
    const question = knownQuestion(item.question);
    /** @type {import('../homework/card/buildQuestionCard.js').QuestionCard | null} */
    let card = null;
    const made = buildQuestionCard({
      number,
      item: {},
      question,
      params: questionParams(question, item.seed ?? ROOM_SEED),
      saved: null,
      lecture: () => true,
      // A prediction's panel would give the answer away: it waits for this question's reveal.
      panelsAllowed: () => question.kind !== 'predict' || Boolean(card?.revealed()),
      onAnswer: () => {},
      onFrame: (frame) => frames.add(frame),
    });
    card = made;
    const reveal = button(t('reveal'), 'lecture-reveal');
    reveal.addEventListener('click', () => { made.reveal(); reveal.disabled = true; });
    made.element.append(reveal);
    section.append(made.element);
    return made;
  });
  window.addEventListener('message', (event) => {
    // Looked up when the message comes: a card makes its frame before it is on the page, without a window yet.
    const frame = [...frames].find((f) => f.contentWindow === event.source);
    /** @type {unknown} a frame's message, data until it is checked */
    const data = event.data;
    const field = (/** @type {string} */ key) => (typeof data === 'object' && data !== null ? Reflect.get(data, key) : undefined);
    if (!frame || field('type') !== 'fresnel-lab:size') return;
    const height = Number(field('height'));
    if (Number.isFinite(height)) frame.style.height = `${Math.min(3000, Math.max(160, Math.ceil(height) + 2))}px`;
  });
  // The page's theme and projector mode reach the panels in their frames.
  window.addEventListener('fresnel-lab:theme', ({ detail }) => {
    for (const frame of frames) {
      frame.contentWindow?.postMessage({ type: 'fresnel-lab:theme', theme: detail.scheme }, '*');
      frame.contentWindow?.postMessage({ type: 'fresnel-lab:projector', on: detail.projector }, '*');
    }
  });
  return cards;
}
