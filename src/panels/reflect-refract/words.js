// @ts-check
// What the reflect-refract panel says of its bands: the lecture's captions for how much reflection
// there is, in the page's language (read when shown, never when the module loads).
import english from 'virtual:messages/en/reflect-refract';
import { messages } from '../../i18n/messages.js';

const t = messages('reflect-refract', english);

/** The caption of a band of physics.js (REFLECTION_BANDS, NO_REFLECTION). */
export const bandLabel = (/** @type {{ id: string }} */ band) => t(`band.${band.id}`);
