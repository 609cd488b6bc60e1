// The sounds of the audio trace, made with the Web Audio API (oscillators and gain envelopes:
// nothing is downloaded). A tone at the pitch of the value under the cursor (a sine; a buzzing
// square wave in the total-internal-reflection range), two high blips at the Brewster angle, a
// falling knock at the critical angle, and a sweep of the whole curve. Every sound is also
// written to `log`, which is what the tests read (a headless browser has no speakers).

const BLIPS_HZ = [1568, 2093]; // G6 then C7: above the trace's two octaves, so never mistaken for a value
const KNOCK_HZ = [330, 110]; // a falling triangle wave, below them

/** The page's sound: one AudioContext, made on the first sound (a key press or a click allows it). */
export function createTraceSound() {
  const Context = globalThis.AudioContext ?? globalThis.webkitAudioContext;
  /** @type {AudioContext | null} */
  let audio = null;
  let playing = []; // oscillators still to stop, for stop()
  const log = [];

  const context = () => {
    audio ??= new Context();
    if (audio.state === 'suspended') audio.resume().catch(() => {}); // resumed by this gesture, or the next
    return audio;
  };

  /** An oscillator through a gain from `start` to `end` (seconds on the context's clock). */
  function voice(type, start, end) {
    const ctx = context();
    const osc = ctx.createOscillator();
    osc.type = type;
    const gain = ctx.createGain();
    gain.gain.setValueAtTime(0, start);
    osc.connect(gain).connect(ctx.destination);
    osc.start(start);
    osc.stop(end + 0.05);
    playing.push(osc);
    osc.onended = () => { playing = playing.filter((o) => o !== osc); };
    return { osc, gain: gain.gain };
  }

  /** A short note: rises in 10 ms, fades by `length`. */
  function note(type, hz, start, length, level) {
    const { osc, gain } = voice(type, start, start + length);
    osc.frequency.setValueAtTime(hz, start);
    gain.linearRampToValueAtTime(level, start + 0.01);
    gain.exponentialRampToValueAtTime(0.0001, start + length);
    return osc;
  }

  function cueAt(kind, start) {
    if (kind === 'brewster') BLIPS_HZ.forEach((hz, i) => note('sine', hz, start + i * 0.07, 0.06, 0.18));
    else {
      const osc = note('triangle', KNOCK_HZ[0], start, 0.2, 0.35);
      osc.frequency.exponentialRampToValueAtTime(KNOCK_HZ[1], start + 0.18);
    }
  }

  return {
    available: typeof Context === 'function',
    log,
    /** The value under the cursor; cues (landmarks just passed) after it. */
    tone(hz, { tir = false, cues = [] } = {}) {
      log.push({ kind: 'tone', hz, tir, cues: [...cues] });
      if (!this.available || hz == null) return;
      this.stop();
      const start = context().currentTime + 0.01;
      // A square wave carries more energy per unit of gain: quieter, so both sound alike in loudness.
      note(tir ? 'square' : 'sine', hz, start, 0.16, tir ? 0.06 : 0.2);
      cues.forEach((kind, i) => cueAt(kind, start + 0.18 + i * 0.25));
    },
    /** A whole curve (audioTraceMath.sweepPlan): its pitch glides, the cues sound where they fall. */
    sweep(plan) {
      log.push({ kind: 'sweep', seconds: plan.seconds, points: plan.points.length, cues: plan.cues.map((c) => c.kind) });
      if (!this.available) return;
      this.stop();
      const start = context().currentTime + 0.02;
      const end = start + plan.seconds;
      const sine = voice('sine', start, end);
      const square = voice('square', start, end);
      const first = plan.points.find((p) => p.hz != null)?.hz ?? BLIPS_HZ[0];
      sine.osc.frequency.setValueAtTime(first, start);
      square.osc.frequency.setValueAtTime(first, start);
      for (const { t, hz, tir } of plan.points) {
        if (hz == null) continue;
        sine.osc.frequency.linearRampToValueAtTime(hz, start + t);
        square.osc.frequency.linearRampToValueAtTime(hz, start + t);
        sine.gain.linearRampToValueAtTime(tir ? 0 : 0.16, start + t);
        square.gain.linearRampToValueAtTime(tir ? 0.05 : 0, start + t);
      }
      sine.gain.linearRampToValueAtTime(0, end);
      square.gain.linearRampToValueAtTime(0, end);
      plan.cues.forEach(({ kind, t }) => cueAt(kind, start + t));
    },
    /** Silence now (a new sound replaces the last one; the trace turned off). */
    stop() {
      for (const osc of playing) {
        try { osc.stop(); } catch { /* not started yet, or already stopped */ }
      }
      playing = [];
    },
    close() {
      this.stop();
      audio?.close().catch(() => {});
      audio = null;
    },
  };
}
