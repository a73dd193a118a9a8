// One browser session for the web peers: a local HTTP server (scene_server.mjs) for the npm
// packages, this folder and the files the scene names, and Debian's Chromium (headless, WebGL
// through ANGLE on the machine's GL: Mesa llvmpipe without a GPU, the same rasteriser ssaolab's EGL
// context gets) with peers.html loaded and the scene set up. run_peers.mjs (make peers) and run_engine.mjs (ssaolab tune --engine) share it.
// The scene is untrusted: the browser reaches nothing but that server, and a page that passes its
// memory or time limit is killed with one line on stderr (the caller reads the last line).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from './scene_server.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));

// Arguments as --key value pairs.
export function parseArgs(argv, need, tool) {
    const args = {};
    for (let i = 2; i < argv.length; i += 2) args[argv[i].replace(/^--/, '')] = argv[i + 1];
    for (const k of need) if (!args[k]) { console.error(`${tool}: missing --${k}`); process.exit(2); }
    return args;
}

// The rows of a GL read (bottom-up) as a binary PGM (top-down), one byte per pixel.
export function pgmBytes(aoBase64, width, height) {
    const ao = Buffer.from(aoBase64, 'base64');
    const flipped = Buffer.alloc(ao.length);
    for (let y = 0; y < height; ++y) ao.copy(flipped, (height - 1 - y) * width, y * width, (y + 1) * width);
    return Buffer.concat([Buffer.from(`P5\n${width} ${height}\n255\n`), flipped]);
}

// An integer from the environment within [lo, hi]; `fallback` when unset.
function envInteger(name, fallback, lo, hi) {
    const v = process.env[name];
    if (v === undefined || v === '') return fallback;
    if (!/^[0-9]{1,9}$/.test(v) || Number(v) < lo || Number(v) > hi)
        throw new Error(`${name} must be an integer in [${lo}, ${hi}], not ${JSON.stringify(v.slice(0, 40))}`);
    return Number(v);
}

// The browser's limits: resident memory of all its processes (MiB) and seconds per page call.
export function browserLimits({ maxMib, maxSeconds } = {}) {
    return { maxMib: maxMib ?? envInteger('SSAOLAB_BROWSER_MAX_MIB', 2048, 256, 65536),
             maxSeconds: maxSeconds ?? envInteger('SSAOLAB_BROWSER_MAX_SECONDS', 300, 1, 86400) };
}

// The pids below `root`, from /proc's parent links: Chromium and everything it started.
function descendants(root) {
    const children = new Map();
    for (const name of fs.readdirSync('/proc')) {
        if (!/^[0-9]+$/.test(name)) continue;
        try {
            const stat = fs.readFileSync(`/proc/${name}/stat`, 'utf8');
            const ppid = Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]); // the name may hold ')'
            if (!children.has(ppid)) children.set(ppid, []);
            children.get(ppid).push(Number(name));
        } catch { /* gone meanwhile */ }
    }
    const out = [], todo = [root];
    while (todo.length) for (const c of children.get(todo.pop()) ?? []) { out.push(c); todo.push(c); }
    return out;
}

// A process's share of resident memory: PSS splits shared pages among their mappers, so the sum
// counts Chromium's binary and shared buffers once (VmRSS where smaps_rollup can't be read; 0 once gone).
function residentBytes(pid) {
    for (const [file, key] of [['smaps_rollup', 'Pss'], ['status', 'VmRSS']]) {
        try {
            const m = new RegExp(`^${key}:\\s+(\\d+) kB`, 'm').exec(fs.readFileSync(`/proc/${pid}/${file}`, 'utf8'));
            if (m) return Number(m[1]) * 1024;
        } catch { /* unreadable or gone */ }
    }
    return 0;
}

// Ends the run at once: SIGKILL to every browser process, one line, exit 1 (nothing printed after it).
function stopSession(tool, line) {
    for (const pid of descendants(process.pid)) try { process.kill(pid, 'SIGKILL'); } catch { /* gone */ }
    console.error(`${tool}: ${line}`);
    process.exit(1);
}

// Every 250 ms, the summed PSS of the browser's processes against the limit. Returns the watch's end.
function watchMemory(maxMib, stop) {
    const timer = setInterval(() => {
        const pids = descendants(process.pid);
        const bytes = pids.reduce((sum, pid) => sum + residentBytes(pid), 0);
        if (bytes > maxMib * 1048576)
            stop(`the browser passed its memory limit of ${maxMib} MiB (${Math.round(bytes / 1048576)} MiB in ${pids.length} `
                 + 'processes) - stopped');
    }, 250);
    timer.unref(); // never what keeps node alive
    return () => clearInterval(timer);
}

// Chromium with no network: only this session's server resolves, and the page's requests go nowhere else.
async function launchBrowser(chromium) {
    return chromium.launch({
        executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
        args: ['--use-gl=angle', '--use-angle=gl-egl', '--ignore-gpu-blocklist', '--enable-gpu',
               '--disable-gpu-vsync', '--disable-frame-rate-limit', '--no-sandbox',
               '--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1', '--js-flags=--max-old-space-size=1024'],
    });
}

// Opens the session on `page` (peers.html: the three.js family; babylon.html: Babylon.js;
// playcanvas.html: PlayCanvas; filament.html: Filament); `camera`
// is ssaolab's metrics.json camera of the first view, `radius` R in scene units; maxMib and
// maxSeconds override browserLimits' defaults; onLate(what), when given, is called before a page
// call past its time limit stops the session. Returns { page, setup, evaluate(what, fn, arg,
// seconds) (page.evaluate within `seconds`, at most maxSeconds), failed(), close() }.
export async function openSession({ modules, sceneFile, width, height, camera, radius, tool, maxMib, maxSeconds,
                                    page: pageFile = 'peers.html', onLate }) {
    const limits = browserLimits({ maxMib, maxSeconds });
    modules = path.resolve(modules);
    const { chromium } = await import(path.join(modules, 'playwright-core', 'index.mjs'));
    const pages = ['peers.html', 'babylon.html', 'playcanvas.html', 'filament.html'];
    if (!pages.includes(pageFile)) throw new Error(`no page '${pageFile}' (${pages.join(', ')})`);
    const roots = { page: here };
    for (const m of ['three', 'n8ao', 'postprocessing', 'babylonjs', 'babylonjs-loaders', 'playcanvas', 'filament'])
        if (fs.existsSync(path.join(modules, m))) roots[m] = path.join(modules, m);
    const server = await startServer({ sceneFile: path.resolve(sceneFile), roots });
    const stop = (line) => stopSession(tool, line);
    let browser, endWatch = () => {};
    try {
        browser = await launchBrowser(chromium);
        endWatch = watchMemory(limits.maxMib, stop);
    } catch (e) {
        await server.close();
        throw e;
    }
    let failed = false;
    const close = async () => { endWatch(); await browser.close(); await server.close(); };
    const evaluate = async (what, fn, arg, seconds = limits.maxSeconds) => {
        const limit = Math.min(seconds, limits.maxSeconds);
        const late = () => {
            onLate?.(what); // the caller's record of what hung, before the browser is stopped
            stop(`the page took over ${Math.round(limit)} s (${what}) - stopped`);
        };
        const timer = setTimeout(late, limit * 1000);
        try { return await page.evaluate(fn, arg); } finally { clearTimeout(timer); }
    };
    let page;
    try {
        const context = await browser.newContext({ viewport: { width, height } });
        const origin = `http://127.0.0.1:${server.port}/`;
        await context.route('**/*', (route) => { // data: and blob: never come here
            const url = route.request().url();
            if (url.startsWith(origin)) return route.continue().catch(() => {}); // the page may be gone
            route.abort('blockedbyclient').catch(() => {});
            stop(`the scene asked for a network resource (${url.length > 200 ? `${url.slice(0, 200)}...` : url}) - refused`);
        });
        page = await context.newPage();
        page.on('pageerror', (e) => { console.error(`${tool}: page error: ${e.message}`); failed = true; });
        page.on('console', (m) => { if (m.type() === 'error') console.error(`${tool}: ${m.text()}`); });
        await page.goto(`${origin}page/${pageFile}`);
        await page.waitForFunction(() => window.peersReady === true, null, { timeout: 60000 });
        const setup = await evaluate('setting up the scene', (c) => window.setupPeers(c),
                                     { scene: server.sceneUrl, width, height, radius, camera });
        return { page, setup, evaluate, failed: () => failed, close };
    } catch (e) {
        await close();
        throw e;
    }
}
