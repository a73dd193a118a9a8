// Runs the web peers (peers.js) in Debian's Chromium (session.mjs) and writes each peer's AO as a
// PGM plus peers.json with the timings. .ci/peers.sh scores the PGMs against ssaolab's reference
// with `ssaolab render --reference --score`.
//
// node run_peers.mjs --modules DIR --scene FILE.gltf --metrics metrics.json --radius R
//                    --size WxH [--frames N] [--peers ssao,ssao:min=0.5,sao,gtao,n8ao] --out DIR
import fs from 'node:fs';
import path from 'node:path';
import { openSession, parseArgs, pgmBytes } from './session.mjs';

const args = parseArgs(process.argv, ['modules', 'scene', 'metrics', 'radius', 'size', 'out'], 'run_peers');
const [width, height] = args.size.split('x').map(Number);
const frames = Number(args.frames ?? 20);
const peers = (args.peers ?? 'ssao,sao,gtao,n8ao').split(',');
const metrics = JSON.parse(fs.readFileSync(args.metrics, 'utf8'));
let session;
try {
    session = await openSession({ modules: args.modules, sceneFile: args.scene, width, height,
                                  camera: metrics.camera, radius: Number(args.radius), tool: 'run_peers' });
} catch (e) {
    console.error(`run_peers: ${e.message.split('\n')[0]}`);
    process.exit(1);
}
try {
    const { evaluate, setup } = session;
    console.log(`run_peers: ${setup.renderer}; three.js r${setup.three}; ${setup.hidden} of ${setup.meshes} meshes transparent (hidden); ${setup.flipped} vertex normals turned to their winding`);
    fs.mkdirSync(args.out, { recursive: true });
    const results = { renderer: setup.renderer, three_revision: setup.three, width, height, frames,
                      radius: Number(args.radius), hidden_meshes: setup.hidden, turned_normals: setup.flipped, peers: [] };
    for (const spec of peers) { // name[:key=value[:key=value]]
        const [name, ...kv] = spec.split(':');
        const opts = Object.fromEntries(kv.map((t) => t.split('=')).map(([k, v]) => [k, Number(v)]));
        const label = [name, ...kv.map((t) => t.replace('=', ''))].join('_');
        const r = await evaluate(label, ([n, o, f]) => window.runPeer(n, o, f), [name, opts, frames]);
        fs.writeFileSync(path.join(args.out, `${label}.pgm`), pgmBytes(r.ao, width, height));
        console.log(`run_peers: ${label}: frame ${r.frame_ms.toFixed(1)} ms, RenderPass alone ${r.plain_ms.toFixed(1)} ms, AO + denoise ${r.ao_ms.toFixed(1)} ms`);
        results.peers.push({ name, label, settings: opts, frame_ms: r.frame_ms, plain_ms: r.plain_ms, ao_ms: r.ao_ms, image: `${label}.pgm` });
    }
    fs.writeFileSync(path.join(args.out, 'peers.json'), JSON.stringify(results, null, 1));
} finally {
    await session.close();
}
process.exit(session.failed() ? 1 : 0);
