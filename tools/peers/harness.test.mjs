// What the harness pages share, where it can run outside a browser: the gamma decode PlayCanvas's
// output needs (its compose pass writes pow(ao, 1 / 2.2) to the canvas), the seeded noise and the
// timed job's numbers. node --test tools/peers/harness.test.mjs
import assert from 'node:assert/strict';
import test from 'node:test';
import { framesDone, gammaDecodeTable, kTimedMs, seededRandom, timedFrames, timedJob } from './harness.js';

test('a gamma-encoded byte decodes to the linear AO it encoded', () => {
    const t = gammaDecodeTable(2.2);
    assert.equal(t[0], 0);
    assert.equal(t[255], 255);
    for (const ao of [0.1, 0.25, 0.5, 0.75, 0.9]) { // the encoded byte back to within one step
        const encoded = Math.round(255 * Math.pow(ao, 1 / 2.2));
        assert.ok(Math.abs(t[encoded] / 255 - ao) <= 1.5 / 255 + ao * 0.02, `AO ${ao}: ${t[encoded] / 255}`);
    }
    assert.equal(t[186], 127); // 186 / 255 = 0.729 on the canvas is AO 0.729^2.2 = 0.499
});

test('the seeded noise repeats and a timed job is its median less the frame without', () => {
    const a = seededRandom(0x55a0), b = seededRandom(0x55a0);
    for (let i = 0; i < 5; ++i) assert.equal(a(), b());
    assert.deepEqual(timedJob([1, 2, 9], 0.5), { frame_ms: 2, plain_ms: 0.5, ao_ms: 1.5, ao_ms_min: 0.5, ao_ms_max: 8.5,
                                              timed_frames: 3 });
});

test('a job times its frames after 3 warm-ups, and fewer of either once frames are slow', () => {
    const fast = [5, 5, 5, 4, 6, 3];
    assert.equal(framesDone(fast.slice(0, 5), 3), false);
    assert.equal(framesDone(fast, 3), true);
    assert.deepEqual(timedFrames(fast), [3, 4, 6]); // the warm-ups left out, sorted
    const slow = [9000, 12000]; // one warm-up once a frame takes over a second
    assert.equal(framesDone(slow, 10), false);
    assert.deepEqual(timedFrames(slow), [12000]);
    assert.equal(framesDone([...slow, kTimedMs - 12000], 10), true); // the timed frames took kTimedMs
    assert.equal(framesDone([2, 1500, 30000], 10), true);
    assert.deepEqual(timedFrames([2, 1500, 30000]), [30000]);
    assert.equal(framesDone([2, 2, 2], 1), false); // never a job without one timed frame
});
