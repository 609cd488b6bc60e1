// @ts-check
// Data from outside (a file, a message, a link's lecture, the browser's storage) is read by its own
// keys only: a key every object inherits (constructor, toString, __proto__) reads as absent, never
// as the prototype's function, and a value that is no object has no keys at all.

/**
 * Whether a value is an object with keys of its own to read: not null, not an array.
 * @param {unknown} value
 * @returns {value is Record<string, unknown>}
 */
export const isObject = (value) => value !== null && typeof value === 'object' && !Array.isArray(value);

/**
 * `object[key]` where `object` is such an object and has `key` as its own property; else undefined.
 * @param {unknown} object
 * @param {string} key
 * @returns {unknown}
 */
export const own = (object, key) => (isObject(object) && Object.hasOwn(object, key) ? object[key] : undefined);
