"""The HTML report in a real browser (headless Chromium): the verdict and the decision table in the first 1,000
pixels at 1,400 px width, every figure decoded."""

import re
import shutil
import subprocess

import pytest

from stackup.report import write_report

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]
#: Marks the page with what the browser made of it once every image has loaded.
PROBE = """<script>window.addEventListener("load", () => {
  const images = [...document.images];
  const verdict = document.querySelector(".verdict");
  document.body.dataset.images = images.length;
  document.body.dataset.decoded = images.filter(i => i.complete && i.naturalWidth > 100).length;
  document.body.dataset.verdictTop = verdict ? Math.round(verdict.getBoundingClientRect().top) : -1;
  const table = document.querySelector(".verdict + table");
  document.body.dataset.tableBottom = table ? Math.round(table.getBoundingClientRect().bottom) : -1;
});</script>"""


@pytest.mark.skipif(CHROMIUM is None, reason="no Chromium on this machine (.ci/run installs it)")
def test_the_report_renders_with_its_verdict_first_and_every_figure_embedded(snapshot_comparison, tmp_path):
    c = snapshot_comparison
    markdown = write_report(c.dataset, tmp_path, scenarios=c.scenarios, sensitivity=c.sensitivity,
                            tails=c.tails).read_text()
    page = (tmp_path / "report.html").read_text()
    assert "src=\"data:image/png;base64," in page and "file:" not in page  # self-contained
    probe = tmp_path / "probe.html"
    probe.write_text(page.replace("</body>", PROBE + "</body>"))
    dom = subprocess.run([CHROMIUM, *FLAGS, f"--user-data-dir={tmp_path / 'profile'}", "--window-size=1400,1000",
                          "--virtual-time-budget=10000", "--dump-dom", probe.as_uri()],
                         capture_output=True, text=True, timeout=120, check=True).stdout
    images = int(dom.split('data-images="')[1].split('"')[0])
    decoded = int(dom.split('data-decoded="')[1].split('"')[0])
    top = int(dom.split('data-verdict-top="')[1].split('"')[0])
    assert images == 5 and decoded == images  # clearance, contributions, film twice, grades: each decoded
    bottom = int(dom.split('data-table-bottom="')[1].split('"')[0])
    assert 0 <= top < 400 and 0 < bottom <= 1000  # the verdict and the decision table on the first screen
    # the verdict's paragraphs, by their bold openings (what to use; model uncertainty; process scenarios)
    verdict = markdown.split("<!-- verdict -->")[1].split("<!-- /verdict -->")[0]
    openings = re.findall(r"\*\*(.+?)\*\*", verdict)
    assert len(openings) >= 3 and all(f"<strong>{opening}</strong>" in dom for opening in openings)
    assert 'id="methods-and-assumptions"' in dom and 'href="#methods-and-assumptions"' in dom  # one click away
