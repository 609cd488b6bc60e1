// @ts-check
// Who a context or a frame loop belongs to: the host sets the owner while it runs a panel's code
// (its mount, an update), and createContext and onDemand keep the owner current when they are
// made, to report a lost context or a draw that throws to that panel (host/panelFaults.js).

/**
 * @typedef {object} FaultOwner
 * @property {(error: unknown) => void} fail  an error in the owner's code
 * @property {() => void} contextLost  one of its contexts is gone
 * @property {() => void} contextRestored  one came back
 */

/** @type {FaultOwner | null} */
let owner = null;

/**
 * Runs fn with `faults` as the owner of every context and frame loop it makes.
 * @template T
 * @param {FaultOwner} faults
 * @param {() => T} fn
 * @returns {T}
 */
export function ownedBy(faults, fn) {
  const before = owner;
  owner = faults;
  try {
    return fn();
  } finally {
    owner = before;
  }
}

/** The owner of the code that runs now (null outside a panel's mount or update). */
export const currentOwner = () => owner;
