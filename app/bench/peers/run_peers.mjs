// Runs the web peers (peers.js) in Debian's Chromium, headless, WebGL through ANGLE on the
// machine's GL (Mesa llvmpipe without a GPU: the same rasteriser ssaolab's EGL context gets), and
// writes each peer's AO as a PGM plus peers.json with the timings. .ci/peers.sh scores the PGMs
// against ssaolab's reference with `ssaolab score`.
//
// node run_peers.mjs --modules DIR --scene FILE.gltf --metrics metrics.json --radius R
//                    --size WxH [--frames N] [--peers ssao,ssao:min=0.5,sao,gtao,n8ao] --out DIR
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
const need = ['modules', 'scene', 'metrics', 'radius', 'size', 'out'];
for (const k of need) if (!args[k]) { console.error(`run_peers: missing --${k}`); process.exit(2); }
const [width, height] = args.size.split('x').map(Number);
const frames = Number(args.frames ?? 20);
const peers = (args.peers ?? 'ssao,sao,gtao,n8ao').split(',');
const here = path.dirname(fileURLToPath(import.meta.url));
const modules = path.resolve(args.modules), sceneFile = path.resolve(args.scene);
const { chromium } = await import(path.join(modules, 'playwright-core', 'index.mjs'));

const roots = { three: path.join(modules, 'three'), n8ao: path.join(modules, 'n8ao'),
                postprocessing: path.join(modules, 'postprocessing'), page: here,
                scene: path.dirname(sceneFile) };
const types = { '.js': 'text/javascript', '.mjs': 'text/javascript', '.html': 'text/html', '.json': 'application/json',
                '.gltf': 'model/gltf+json', '.glb': 'model/gltf-binary', '.bin': 'application/octet-stream',
                '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.ktx2': 'image/ktx2' };
const server = http.createServer((req, res) => {
    const url = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (url === '/favicon.ico') { res.writeHead(204); res.end(); return; }
    const [, root, ...rest] = url.split('/');
    const base = roots[root];
    const file = base && path.resolve(base, rest.join('/'));
    if (!file || !file.startsWith(base) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
        res.writeHead(404); res.end(); return;
    }
    res.writeHead(200, { 'content-type': types[path.extname(file).toLowerCase()] ?? 'application/octet-stream' });
    fs.createReadStream(file).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const port = server.address().port;

const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--use-gl=angle', '--use-angle=gl-egl', '--ignore-gpu-blocklist', '--enable-gpu',
           '--disable-gpu-vsync', '--disable-frame-rate-limit', '--no-sandbox'],
});
let failed = false;
try {
    const page = await browser.newPage({ viewport: { width, height } });
    page.on('pageerror', (e) => { console.error(`run_peers: page error: ${e.message}`); failed = true; });
    page.on('console', (m) => { if (m.type() === 'error') console.error(`run_peers: ${m.text()}`); });
    await page.goto(`http://127.0.0.1:${port}/page/peers.html`);
    await page.waitForFunction(() => window.peersReady === true, null, { timeout: 60000 });
    const metrics = JSON.parse(fs.readFileSync(args.metrics, 'utf8'));
    const setup = await page.evaluate((c) => window.setupPeers(c), {
        scene: `/scene/${encodeURIComponent(path.basename(sceneFile))}`, width, height,
        radius: Number(args.radius), camera: metrics.camera });
    console.log(`run_peers: ${setup.renderer}; three.js r${setup.three}; ${setup.hidden} of ${setup.meshes} meshes transparent (hidden); ${setup.flipped} vertex normals turned to their winding`);
    fs.mkdirSync(args.out, { recursive: true });
    const results = { renderer: setup.renderer, three_revision: setup.three, width, height, frames,
                      radius: Number(args.radius), hidden_meshes: setup.hidden, turned_normals: setup.flipped, peers: [] };
    for (const spec of peers) { // name[:key=value[:key=value]]
        const [name, ...kv] = spec.split(':');
        const opts = Object.fromEntries(kv.map((t) => t.split('=')).map(([k, v]) => [k, Number(v)]));
        const label = [name, ...kv.map((t) => t.replace('=', ''))].join('_');
        const r = await page.evaluate(([n, o, f]) => window.runPeer(n, o, f), [name, opts, frames]);
        const ao = Buffer.from(r.ao, 'base64');
        const flipped = Buffer.alloc(ao.length); // GL rows are bottom-up; PGM rows top-down
        for (let y = 0; y < height; ++y) ao.copy(flipped, (height - 1 - y) * width, y * width, (y + 1) * width);
        const file = path.join(args.out, `${label}.pgm`);
        fs.writeFileSync(file, Buffer.concat([Buffer.from(`P5\n${width} ${height}\n255\n`), flipped]));
        console.log(`run_peers: ${label}: frame ${r.frame_ms.toFixed(1)} ms, RenderPass alone ${r.plain_ms.toFixed(1)} ms, AO + denoise ${r.ao_ms.toFixed(1)} ms`);
        results.peers.push({ name, label, settings: opts, frame_ms: r.frame_ms, plain_ms: r.plain_ms, ao_ms: r.ao_ms, image: `${label}.pgm` });
    }
    fs.writeFileSync(path.join(args.out, 'peers.json'), JSON.stringify(results, null, 1));
} finally {
    await browser.close();
    server.close();
}
process.exit(failed ? 1 : 0);
