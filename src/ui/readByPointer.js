// Reading a picture where the pointer is: a mouse reads as it hovers, a finger where it taps
// (a tap fires pointerdown but no pointermove) or drags. A mouse leaving the picture clears the
// reading; a lifted finger, which also "leaves", keeps what it tapped in view.

/**
 * read(event): show the reading at event.clientX/Y. clear(): show the hint (optional).
 * Returns a function that removes the listeners.
 */
export function readByPointer(element, read, clear = null) {
  const leave = (event) => { if (event.pointerType !== 'touch') clear?.(); };
  element.addEventListener('pointermove', read);
  element.addEventListener('pointerdown', read);
  element.addEventListener('pointerleave', leave);
  return () => {
    element.removeEventListener('pointermove', read);
    element.removeEventListener('pointerdown', read);
    element.removeEventListener('pointerleave', leave);
  };
}
