// What the harness pages share, where it can run outside a browser: the gamma decode PlayCanvas's
// output needs (its compose pass writes pow(ao, 1 / 2.2) to the canvas), the seeded noise and the
// timed job's numbers. node --test tools/peers/harness.test.mjs
import assert from 'node:assert/strict';
import test from 'node:test';
import { gammaDecodeTable, seededRandom, timedJob } from './harness.js';

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
    assert.deepEqual(timedJob([1, 2, 9], 0.5), { frame_ms: 2, plain_ms: 0.5, ao_ms: 1.5, ao_ms_min: 0.5, ao_ms_max: 8.5 });
});
