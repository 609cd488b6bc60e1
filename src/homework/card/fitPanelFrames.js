// @ts-check
// The panels' frames on a page of question cards (the homework page, a composed lecture's
// questions): each frame takes the height its embed page reports (fresnel-lab:size, within 160 to
// 3000 px), and the page's theme and projector mode reach the panels already open in them.
import { own } from '../../host/own.js';

/**
 * Starts listening; add each panel frame as its card makes it.
 * @returns {{ add: (frame: HTMLIFrameElement) => void }}
 */
export function fitPanelFrames() {
  /** @type {Set<HTMLIFrameElement>} */
  const frames = new Set();
  window.addEventListener('message', (event) => {
    // Looked up when the message comes: a card makes its frame before it is on the page, without a window yet.
    const frame = [...frames].find((f) => f.contentWindow === event.source);
    if (!frame || own(event.data, 'type') !== 'fresnel-lab:size') return;
    const height = Number(own(event.data, 'height'));
    if (Number.isFinite(height)) frame.style.height = `${Math.min(3000, Math.max(160, Math.ceil(height) + 2))}px`;
  });
  window.addEventListener('fresnel-lab:theme', ({ detail }) => {
    for (const frame of frames) {
      frame.contentWindow?.postMessage({ type: 'fresnel-lab:theme', theme: detail.scheme }, '*');
      frame.contentWindow?.postMessage({ type: 'fresnel-lab:projector', on: detail.projector }, '*');
    }
  });
  return { add: (frame) => { frames.add(frame); } };
}
