// scene_server.mjs against hostile scenes and raw request paths (no browser):
// node --test tools/peers/scene_server.test.mjs
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import http from 'node:http';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { startServer, sceneAllowlist, uriKey, requestComponents } from './scene_server.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'scene-server-'));
const put = (rel, bytes) => {
    const file = path.join(tmp, rel);
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, bytes);
    return file;
};
const gltf = { asset: { version: '2.0' },
               buffers: [{ uri: 'buf.bin', byteLength: 4 }, { uri: 'data:application/octet-stream;base64,AAAA' }],
               images: [{ uri: 'tex/a%20b.png' }, { uri: '..%2Fscn-private%2Fsecret.png' },
                        { uri: 'http://127.0.0.1:1/x.png' }, { uri: '%2e%2e/secret.png' }, { uri: 'link.png' }, { uri: '/etc/passwd' }, { uri: '//host/x.png' },
                        { uri: 'file:///etc/passwd' }, { uri: 'tex/../../scn-private/secret.png' }, { bufferView: 0 }] };
const sceneFile = put('scn/scene.gltf', JSON.stringify(gltf));
put('scn/buf.bin', 'BUF!');
put('scn/tex/a b.png', 'PNG a b');
put('scn/other.txt', 'not referenced');
put('scn-private/secret.png', 'SECRET');
put('secret.png', 'SECRET ABOVE');
fs.symlinkSync('../scn-private/secret.png', path.join(tmp, 'scn/link.png'));
put('mods/three/build/three.module.js', 'export const REVISION = 1;');
put('mods/three-evil/x.js', 'EVIL');
fs.symlinkSync('../../scn-private/secret.png', path.join(tmp, 'mods/three/escape.js'));
put('page/peers.html', '<!doctype html>');
const roots = { three: path.join(tmp, 'mods/three'), page: path.join(tmp, 'page') };

// A GET of a raw path, sent exactly as written; a server that never answers is an error, not a hang.
function get(port, rawPath) {
    return new Promise((resolve, reject) => {
        const req = http.request({ host: '127.0.0.1', port, path: rawPath, agent: false }, (res) => {
            const chunks = [];
            res.on('data', (c) => chunks.push(c));
            res.on('end', () => resolve({ status: res.statusCode, body: Buffer.concat(chunks).toString() }));
        });
        req.on('error', reject);
        req.setTimeout(5000, () => req.destroy(Object.assign(new Error('no answer'), { code: 'no answer' })));
        req.end();
    });
}

let server;
before(async () => { server = await startServer({ roots, sceneFile }); });
after(async () => { await server?.close(); fs.rmSync(tmp, { recursive: true, force: true }); });

test('serves the scene, what it references and the module roots', async () => {
    for (const [p, body] of [['/scene/scene.gltf', JSON.stringify(gltf)], ['/scene/buf.bin', 'BUF!'],
                             ['/scene/tex/a%20b.png', 'PNG a b'], ['/scene/tex/a%20b.png?v=1', 'PNG a b'],
                             ['/three/build/three.module.js', 'export const REVISION = 1;'],
                             ['/page/peers.html', '<!doctype html>']]) {
        assert.deepEqual(await get(server.port, p), { status: 200, body }, p);
    }
    assert.equal(server.sceneUrl, '/scene/scene.gltf');
});

test('refuses every hostile path', async () => {
    const served = [];
    for (const p of ['/scene/..%2Fscn-private%2Fsecret.png', '/scene/%2e%2e/scn-private/secret.png',
                     '/scene/%2E%2E/secret.png', '/scene/../scn-private/secret.png', '/scene/other.txt',
                     '/scene/link.png', '/scene/tex%2Fa%20b.png', '/scene/tex/./a%20b.png', '/scene//buf.bin',
                     '/scene/buf.bin%00', '/scene/..%5Cscn-private%5Csecret.png', '/scene/%ZZ', '/scene/', '/scene',
                     '/page/../../etc/passwd', '/page/%2e%2e/%2e%2e/etc/passwd', '/three/..%2F..%2Fetc%2Fpasswd',
                     '/three/..%2Fthree-evil%2Fx.js', '/three/%2e%2e/three-evil/x.js', '/three/escape.js',
                     '/three/build', '/nope/x.js', '/__proto__/x', '/etc/passwd', 'http://127.0.0.1/scene/buf.bin']) {
        const r = await get(server.port, p).catch((e) => ({ status: e.code, body: '' }));
        if (!(r.status === 404 || r.status === 400) || /SECRET|EVIL|root:/.test(r.body)) served.push(`${p}: ${r.status}`);
    }
    assert.deepEqual(served, []); // all at once, so a regression shows every path it lets through
    assert.equal((await get(server.port, '/scene/buf.bin')).status, 200, 'still up after the hostile requests');
});

test('the allowlist holds only plain relative references', () => {
    assert.deepEqual([...sceneAllowlist(sceneFile)].sort(), ['buf.bin', 'link.png', 'scene.gltf', 'tex/a b.png']);
    for (const u of ['http://x/a.png', 'HTTPS://x', 'file:///etc/passwd', 'blob:x', 'data:,x', '/a.png', '//h/a.png',
                     '\\\\h\\a.png', '../a.png', 'a/%2e%2e/b.png', 'a%2Fb.png', 'a%5Cb.png', 'a%00.png', '%ZZ', '', '.', 42])
        assert.equal(uriKey(u), null, String(u));
    assert.equal(uriKey('./tex/a%20b.png'), 'tex/a b.png');
    for (const u of ['big.png?x', 'a.png#frag', 'a+b.bin', 'a\tb.png', '.\t./x.png']) assert.equal(uriKey(u), null, u);
    assert.deepEqual(requestComponents('/scene/a%2520b'), ['scene', 'a%20b']); // decoded once, not twice
});

// A .glb of the given JSON and an empty BIN chunk.
function glb(json, { version = 2, chunkType = 0x4e4f534a, claim } = {}) {
    const text = Buffer.from(JSON.stringify(json).padEnd(Math.ceil(JSON.stringify(json).length / 4) * 4, ' '));
    const head = Buffer.alloc(20);
    head.writeUInt32LE(0x46546c67, 0);
    head.writeUInt32LE(version, 4);
    head.writeUInt32LE(20 + text.length, 8);
    head.writeUInt32LE(claim ?? text.length, 12);
    head.writeUInt32LE(chunkType, 16);
    return Buffer.concat([head, text]);
}

test('a .glb: the allowlist comes from its JSON chunk', async () => {
    const file = put('glb/scene.glb', glb({ asset: { version: '2.0' }, buffers: [{ byteLength: 0 }],
                                           images: [{ uri: 'img/t.png' }, { uri: '..%2Fscn-private%2Fsecret.png' }] }));
    put('glb/img/t.png', 'T');
    put('glb/unlisted.png', 'U');
    assert.deepEqual([...sceneAllowlist(file)].sort(), ['img/t.png', 'scene.glb']);
    const s = await startServer({ roots, sceneFile: file });
    try {
        assert.equal((await get(s.port, '/scene/scene.glb')).status, 200);
        assert.deepEqual(await get(s.port, '/scene/img/t.png'), { status: 200, body: 'T' });
        assert.equal((await get(s.port, '/scene/unlisted.png')).status, 404);
        assert.equal((await get(s.port, '/scene/..%2Fscn-private%2Fsecret.png')).status, 404);
    } finally {
        await s.close();
    }
    assert.throws(() => sceneAllowlist(put('glb/v1.glb', glb({}, { version: 1 }))), /not a glTF 2.0 binary/);
    assert.throws(() => sceneAllowlist(put('glb/bin.glb', glb({}, { chunkType: 0x004e4942 }))), /not a glTF 2.0 binary/);
    assert.throws(() => sceneAllowlist(put('glb/long.glb', glb({}, { claim: 0xfffffff0 }))), /runs past the file/);
});
