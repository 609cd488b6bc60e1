// @ts-check
// The lecture being composed, kept in the browser's storage so a reload or a closed tab loses
// nothing. What comes back is untrusted (another page of the origin, an older version, a hand
// edit): it is read by readLecture like a link, and a lecture that cannot be read is named, not used.
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { readLecture } from '../lecture/readLecture.js';

const t = messages('compose', english);

export const DRAFT_KEY = 'fresnel-lab:composer';
const MAX_STORED = 500_000; // characters; a lecture with text on every item is a few kilobytes

/**
 * Saves the lecture data (draftData's, unread: an item still being written is kept too).
 * @param {unknown} data
 * @returns {boolean} false where storage is refused (private mode, full, blocked)
 */
export function saveDraft(data, storage = globalThis.localStorage) {
  try {
    storage.setItem(DRAFT_KEY, JSON.stringify(data));
    return true;
  } catch {
    return false;
  }
}

/**
 * { lecture, problems } from storage: lecture null when nothing is kept or it cannot be read
 * (problems then say why, where there was something).
 * @returns {{ lecture: import('../lecture/readLecture.js').Lecture | null, problems: string[] }}
 */
export function loadDraft(storage = globalThis.localStorage) {
  let text;
  try {
    text = storage.getItem(DRAFT_KEY);
  } catch {
    return { lecture: null, problems: [t('storageRefused')] };
  }
  if (text === null) return { lecture: null, problems: [] };
  if (typeof text !== 'string' || text.length > MAX_STORED) {
    return { lecture: null, problems: [t('storedTooLarge')] };
  }
  /** @type {unknown} */
  let data;
  try {
    data = JSON.parse(text);
  } catch {
    return { lecture: null, problems: [t('storedDamaged')] };
  }
  const read = readLecture(data);
  return read.ok ? { lecture: read.lecture, problems: read.problems } : { lecture: null, problems: read.problems };
}

/** Forgets the kept lecture. */
export function clearDraft(storage = globalThis.localStorage) {
  try {
    storage.removeItem(DRAFT_KEY);
  } catch {
    // Nothing kept where storage is refused.
  }
}
