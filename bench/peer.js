// The benchmark's peer page: three.js's MeshPhysicalMaterial spheres (createPhysicalPeer.js) in a
// canvas filling the frame, answering the hero embed's messages the same way: `set` with nT
// changes the material and draws on the next animation frame, then `rendered` is posted.
// ?clearcoat=0 drops the clear coat (the cheaper, plainer peer).
import { createPhysicalPeer } from '../src/panels/speed-accuracy/createPhysicalPeer.js';

const canvas = document.querySelector('canvas');
let frame = 0;
const peer = createPhysicalPeer(canvas, {
  clearcoat: new URLSearchParams(window.location.search).get('clearcoat') !== '0', // ?clearcoat=0: the plain material
  width: window.innerWidth,
  height: window.innerHeight,
  onFrame: () => {
    frame += 1;
    window.parent.postMessage({ type: 'fresnel-lab:rendered', panel: 'peer', frame }, '*');
  },
});
window.addEventListener('message', (event) => {
  const nT = Number(event.data?.type === 'fresnel-lab:set' ? event.data.params?.nT : NaN);
  if (Number.isFinite(nT)) peer.setParams({ nT });
});
peer.frames.request();
window.parent.postMessage({ type: 'fresnel-lab:ready', panel: 'peer', params: {} }, '*');
