// @ts-check
// A question of a composed lecture, asked of the room as the homework page's lecture mode asks it:
// homework's question card (buildQuestionCard, with its styles) judges nothing until the lecturer
// reveals it; a prediction's panel appears with the truth. Loaded only by a lecture that has a question.
import { knownQuestion } from '../homework/questions.js';
import { questionParams } from '../homework/gradeAnswer.js';
import { buildQuestionCard } from '../homework/card/buildQuestionCard.js';
import { fitPanelFrames } from '../homework/card/fitPanelFrames.js';
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
  const frames = fitPanelFrames();
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
      onFrame: frames.add,
    });
    card = made;
    const reveal = button(t('reveal'), 'lecture-reveal');
    reveal.addEventListener('click', () => { made.reveal(); reveal.disabled = true; });
    made.element.append(reveal);
    section.append(made.element);
    return made;
  });
  return cards;
}
