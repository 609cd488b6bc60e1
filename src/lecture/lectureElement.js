// @ts-check
// The id of the element that carries a lecture in the page (<script type="application/json" id=…>,
// written by the offline export): a module of its own, so the lecture page can look for the
// element without loading the code that reads a lecture.
export const LECTURE_ELEMENT_ID = 'fresnel-lab-lecture';
