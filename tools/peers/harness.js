// What the harness pages share (peers.js, babylon.js, playcanvas.js, filament.js): the seeded Math.random an
// engine's noise is drawn from, the timed frames, the AO read back, and the table rows' paths.

// The page's canvas, w x h pixels at one CSS pixel each (no device scaling), in the body.
export function pageCanvas(w, h) {
    const canvas = document.createElement('canvas');
    canvas.width = w;
    canvas.height = h;
    canvas.style.width = `${w}px`;
    canvas.style.height = `${h}px`;
    document.body.appendChild(canvas);
    return canvas;
}

// A fixed sequence (mulberry32): restarted before an engine builds its noise, one setting gives one
// image in every session (a tune compares settings measured in different sessions).
export function seededRandom(seed) {
    let s = seed >>> 0;
    return () => {
        s = (s + 0x6D2B79F5) >>> 0;
        let t = Math.imul(s ^ (s >>> 15), s | 1);
        t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
        return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
}

// When a timed job's frames stop. Warm-up: 3 frames, or fewer once one takes over a second (its
// caches are warm after it). Then `frames` timed, or fewer once they took kTimedMs in all: a frame
// that slow is timed far inside its own spread by one, and a setting a driver crawls on (Babylon
// SSAO2 at a wide radius on llvmpipe: docs/engines.md) still ends inside the browser's time limit.
export const kTimedMs = 20000;
export function warmUpFrames(all) {
    for (let i = 0; i < 3 && i < all.length; ++i)
        if (all[i] > 1000) return i + 1;
    return 3;
}
export function framesDone(all, frames) {
    const w = warmUpFrames(all);
    if (all.length < w) return false;
    const timed = all.slice(w);
    return timed.length >= frames || (timed.length > 0 && timed.reduce((a, b) => a + b, 0) >= kTimedMs);
}
export const timedFrames = (all) => all.slice(warmUpFrames(all)).sort((a, b) => a - b);

// Every timed frame's ms, sorted (framesDone): `draw` then a 1-pixel readPixels (WebGL has no GPU
// timer on llvmpipe, and the read waits for the GPU process to finish the frame).
export function frameTimes(gl, draw, frames) {
    const px = new Uint8Array(4), all = [];
    while (!framesDone(all, frames)) {
        const t0 = performance.now();
        draw();
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
        all.push(performance.now() - t0);
    }
    return timedFrames(all);
}

export const median = (sorted) => sorted[Math.floor(sorted.length / 2)];

// A timed job's numbers: the median frame with the engine, the frame without, their difference
// (the AO's time), the fastest and slowest frame's, and how many frames were timed.
export function timedJob(times, plainMs) {
    const frame = median(times);
    return { frame_ms: frame, plain_ms: plainMs, ao_ms: frame - plainMs, ao_ms_min: times[0] - plainMs,
             ao_ms_max: times[times.length - 1] - plainMs, timed_frames: times.length };
}

// readAo's `decode` for an output written as pow(linear, 1 / gamma): byte -> the linear byte.
export function gammaDecodeTable(gamma) {
    return Uint8Array.from({ length: 256 }, (_, b) => Math.round(255 * Math.pow(b / 255, gamma)));
}

// The canvas's red channel (the AO), one byte per pixel, rows bottom-up as GL reads them, base64.
// `decode` (optional): 256 bytes mapping what the canvas holds to linear AO, for an engine whose
// last pass encodes its output.
export function readAo(gl, w, h, decode) {
    const rgba = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    const ao = new Uint8Array(w * h);
    for (let i = 0; i < w * h; ++i) ao[i] = decode ? decode[rgba[4 * i]] : rgba[4 * i];
    return aoBase64(ao);
}

// One byte per pixel (the AO x 255, rows bottom-up) as the base64 runEngine returns.
export function aoBase64(ao) {
    let s = '';
    for (let i = 0; i < ao.length; i += 0x8000) s += String.fromCharCode.apply(null, ao.subarray(i, i + 0x8000));
    return btoa(s);
}

export function readPath(o, path) {
    for (const k of path.split('.')) o = o?.[k];
    return o;
}

export function writePath(o, path, v) {
    const keys = path.split('.'), last = keys.pop();
    for (const k of keys) o = o[k];
    o[last] = v;
}

// Each row's value where its table reads it.
export function readParams(o, params) {
    return Object.fromEntries(params.map((p) => {
        const v = readPath(o, p.read);
        return [p.name, p.type === 'boolean' ? Boolean(v) : Number(v)];
    }));
}
