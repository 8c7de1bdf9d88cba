// The browser side of bench/dashboard_bench.sh.
//   node dashboard_bench.js fleet URL JOBS LOADS   the fleet page LOADS times: navigation to table
//   node dashboard_bench.js pages URL JOB N        N pages of /job/JOB open until the job ends; prints
//                                                  "pages ready" once loaded and the browser is quiet
//                                                  (a fresh page's start-up is not what an open page
//                                                  costs), at the end the browser's CPU seconds (all
//                                                  its processes) since then
//   node dashboard_bench.js follow URL JOB         /job/JOB open from before the job starts until it
//                                                  ends: each text of its progress line as
//                                                  "<Unix s>\t<text>", then "end\t<state>"
//                                                  (bench/progress_honesty.sh)
"use strict";
const puppeteer = require("puppeteer-core");
const { execSync } = require("child_process");

// CPU seconds of a process and all its descendants (/proc, clock ticks).
function treeCpuSeconds(root) {
  const hz = Number(execSync("getconf CLK_TCK"));
  const stats = execSync("cat /proc/[0-9]*/stat 2>/dev/null || true").toString().split("\n").filter((l) => l);
  const procs = stats.map((l) => {
    const f = l.slice(l.lastIndexOf(")") + 2).split(" ");
    return { pid: Number(l.split(" ")[0]), ppid: Number(f[1]), cpu: (Number(f[11]) + Number(f[12])) / hz };
  });
  const tree = new Set([root]);
  for (let grew = true; grew;) {
    grew = false;
    for (const p of procs) if (!tree.has(p.pid) && tree.has(p.ppid)) { tree.add(p.pid); grew = true; }
  }
  return procs.filter((p) => tree.has(p.pid)).reduce((s, p) => s + p.cpu, 0);
}

async function main() {
  const [mode, url, a, b] = process.argv.slice(2);
  const browser = await puppeteer.launch({ executablePath: "/usr/bin/chromium", headless: true,
                                           args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-proxy-server"] });
  try {
    if (mode === "fleet") {
      const times = [];
      const page = await browser.newPage();
      await page.setViewport({ width: 1400, height: 900 });
      for (let i = 0; i < Number(b); ++i) {
        await page.goto(url + "/", { waitUntil: "domcontentloaded" });
        await page.waitForFunction((n) => document.querySelectorAll("#fleet tbody tr").length >= n, { timeout: 20000 }, Number(a));
        // From the start of navigation to the rows drawn (performance.now() counts from there).
        times.push(Number(await page.$eval("#main", (m) => m.dataset.firstRowsMs)));
      }
      times.sort((x, y) => x - y);
      console.log(`fleet page with ${a} jobs, ${times.length} loads: navigation to table drawn median ` +
                  `${times[Math.floor(times.length / 2)].toFixed(0)} ms, max ${times[times.length - 1].toFixed(0)} ms ` +
                  `(${times.map((t) => t.toFixed(0)).join(", ")})`);
    } else if (mode === "follow") {
      const page = await browser.newPage();
      await page.exposeFunction("recordLine", (t, text) => console.log(`${(t / 1000).toFixed(3)}\t${text}`));
      await page.goto(url + "/job/" + a, { waitUntil: "domcontentloaded" });
      await page.waitForSelector("#progress-line");
      await page.evaluate(() => {
        const line = document.getElementById("progress-line");
        const record = () => window.recordLine(performance.timeOrigin + performance.now(), line.textContent);
        new MutationObserver(record).observe(line, { childList: true, characterData: true, subtree: true });
        record();
      });
      await page.waitForFunction(() => ["done", "incomplete", "failed", "cancelled"].includes(document.getElementById("job-summary").dataset.state),
                                 { timeout: 0, polling: 200 });
      await new Promise((r) => setTimeout(r, 1000));  // the final line follows the final state
      const state = await page.$eval("#job-summary", (e) => e.dataset.state);
      console.log(`end\t${state}`);
    } else {
      const pages = [];
      // A context each, as if in browsers of their own: one browser keeps at most six connections
      // to a server, and each open page's event stream holds one (docs/dashboard.md).
      for (let i = 0; i < Number(b); ++i) {
        const page = await (await browser.createBrowserContext()).newPage();
        await page.goto(url + "/job/" + a, { waitUntil: "domcontentloaded" });
        pages.push(page);
      }
      // Quiet: less than 0.1 CPU s in a second (at most 30 s). Right after loading, ten pages
      // still spend ~3 CPU s starting up (measured), which would fall into the sweep's time.
      for (let i = 0, before = treeCpuSeconds(browser.process().pid); i < 30; ++i) {
        await new Promise((r) => setTimeout(r, 1000));
        const now = treeCpuSeconds(browser.process().pid);
        if (now - before < 0.1) break;
        before = now;
      }
      console.log("pages ready");
      const startup = treeCpuSeconds(browser.process().pid);
      await pages[0].waitForFunction(() => ["done", "failed", "cancelled"].includes(document.getElementById("job-summary").dataset.state),
                                     { timeout: 0, polling: 500 });
      const spent = treeCpuSeconds(browser.process().pid) - startup;
      await new Promise((r) => setTimeout(r, 1000));  // the page draws what arrived at most every 0.5 s
      const points = await pages[0].$eval("#result-chart", (e) => e.dataset.points);
      console.log(`browser ${spent.toFixed(2)} CPU s after the pages loaded ` +
                  `(${startup.toFixed(2)} s to start, load and settle them; ${points} points drawn)`);
    }
  } finally {
    await browser.close();
  }
}
main().catch((e) => { console.error("dashboard_bench: " + e.message); process.exit(1); });
