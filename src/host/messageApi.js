// The message API between a slide deck and an embedded panel (window.postMessage):
//   deck → panel  {type:'fresnel-lab:set', params}   validated; rejected values answer fresnel-lab:error
//   deck → panel  {type:'fresnel-lab:get'}           answers {type:'fresnel-lab:state', panel, params}
//   panel → deck  {type:'fresnel-lab:state', …}       also after a change made in the panel (a control, a drag)
//   panel → deck  {type:'fresnel-lab:ready', panel, params} once mounted
//   panel → deck  {type:'fresnel-lab:rendered', panel, frame} after each frame drawn
// Anything else is ignored. Nothing from a message is evaluated or inserted as HTML.

/** The message as { kind, params } when it has one of the accepted shapes, else null. */
export function parseMessage(data) {
  if (!data || typeof data !== 'object' || Array.isArray(data)) return null;
  if (data.type === 'fresnel-lab:get') return { kind: 'get' };
  if (data.type === 'fresnel-lab:set') {
    const { params } = data;
    if (!params || typeof params !== 'object' || Array.isArray(params)) return null;
    return { kind: 'set', params };
  }
  return null;
}

/** Plain copy of the values (no prototype, no functions) for posting. */
function snapshot(values) {
  return JSON.parse(JSON.stringify(values));
}

export function connectMessages(host, { parent = window.parent } = {}) {
  // Replies go to whoever asked; announcements only to a real parent (not to ourselves).
  const post = (target, message) => target?.postMessage(message, '*');
  const announce = (message) => { if (parent && parent !== window) post(parent, message); };
  const onMessage = (event) => {
    const message = parseMessage(event.data);
    if (!message) return;
    const reply = event.source ?? parent;
    if (message.kind === 'get') {
      post(reply, { type: 'fresnel-lab:state', panel: host.id, params: snapshot(host.values) });
      return;
    }
    const { rejected } = host.set(message.params);
    if (rejected.length) {
      const text = rejected.map((r) => `${r.key}: ${String(r.raw).slice(0, 40)} ${r.reason}`).join('; ');
      post(reply, { type: 'fresnel-lab:error', panel: host.id, message: `Rejected ${text}` });
    }
    post(reply, { type: 'fresnel-lab:state', panel: host.id, params: snapshot(host.values) });
  };
  window.addEventListener('message', onMessage);
  // Changes the deck did not ask for (a control, a drag, the page): the new state, at most once per
  // animation frame, so a slider drag does not flood the deck.
  let pending = 0;
  const stopListening = host.onChange(({ source }) => {
    if (source === 'api' || pending) return;
    pending = requestAnimationFrame(() => {
      pending = 0;
      announce({ type: 'fresnel-lab:state', panel: host.id, params: snapshot(host.values) });
    });
  });
  return {
    ready: () => announce({ type: 'fresnel-lab:ready', panel: host.id, params: snapshot(host.values) }),
    rendered: (frame) => announce({ type: 'fresnel-lab:rendered', panel: host.id, frame }),
    disconnect() {
      window.removeEventListener('message', onMessage);
      stopListening();
      cancelAnimationFrame(pending);
    },
  };
}
