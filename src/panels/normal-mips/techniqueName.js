// What each technique is called where a reader sees it, in the page's language; the ids stay in
// URLs, files and the CSV.
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';

const t = messages('normal-mips', english);

/** The name of technique `id` (one of TECHNIQUES: naive, renormalized, toksvig, lean, clean, vmf). */
export const techniqueName = (/** @type {string} */ id) => t(`technique.${id}`);
