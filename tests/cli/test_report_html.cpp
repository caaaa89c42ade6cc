// The HTML reports of `gap`, `replay` and `identify --report`, rendered headlessly by
// Debian's chromium: the page loads, the verdict comes first, every plot is embedded,
// decodes and is not blank, nothing is fetched from outside the file, and a screenshot of
// the page is not blank. Exit 77 (CTest: skipped) only when chromium is not installed.
#include <png.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "../support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

int failures = 0;

void check(bool ok, const std::string& what) {
  if (!ok) {
    std::cerr << "FAILED: " << what << "\n";
    ++failures;
  }
}

// Runs a shell command; returns its exit status and stdout (stderr is discarded: chromium
// chatters about D-Bus).
int run(const std::string& cmd, std::string* out = nullptr) {
  const hstmon_test::CliRun r = hstmon_test::run_command(cmd + " 2>/dev/null");
  if (out != nullptr) *out = r.out;
  return r.exit_code;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string chromium_binary() {
  for (const char* c : {"chromium", "chromium-browser"}) {
    if (run(std::string("command -v ") + c + " >/dev/null") == 0) return c;
  }
  return {};
}

// Added to a copy of the page (the report itself has no script): on load, every image's
// decoded size and how many of its pixels are not white, into a <pre> that --dump-dom shows.
const char* const kProbe = R"(<script>
window.addEventListener('load', () => {
  const out = [];
  for (const img of document.images) {
    let ink = -1;
    if (img.complete && img.naturalWidth > 0) {
      const c = document.createElement('canvas');
      c.width = img.naturalWidth; c.height = img.naturalHeight;
      const g = c.getContext('2d');
      g.fillStyle = '#fff'; g.fillRect(0, 0, c.width, c.height); g.drawImage(img, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
      ink = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200) ++ink;
    }
    out.push(img.naturalWidth + 'x' + img.naturalHeight + ':' + ink);
  }
  const p = document.createElement('pre');
  p.id = 'probe';
  p.textContent = 'IMAGES ' + out.join(' ') + ' END';
  document.body.appendChild(p);
});
</script>)";

// Non-white pixels of a PNG file (libpng's simplified API), or -1 if it cannot be read.
long ink_in_png(const fs::path& file, long* total) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&image, file.c_str()) == 0) return -1;
  image.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> px(PNG_IMAGE_SIZE(image));
  if (png_image_finish_read(&image, nullptr, px.data(), 0, nullptr) == 0) return -1;
  long ink = 0;
  for (std::size_t i = 0; i + 2 < px.size(); i += 3) {
    if (px[i] < 200 || px[i + 1] < 200 || px[i + 2] < 200) ++ink;
  }
  *total = static_cast<long>(image.width) * static_cast<long>(image.height);
  return ink;
}

void check_page(const std::string& chromium, const fs::path& report_dir, std::size_t plots, const std::string& name) {
  const fs::path page = report_dir / "report.html";
  const std::string html = read(page);
  check(!html.empty(), name + ": report.html written");
  if (html.empty()) return;
  // Self-contained: images are data: URIs, no script, no stylesheet or image from elsewhere.
  check(html.find("<script") == std::string::npos, name + ": no script in the report");
  check(std::regex_search(html, std::regex("(src|href)=\"(?!data:)")) == false, name + ": nothing loaded from outside the page");
  const auto verdict = html.find("id=\"verdict\"");
  check(verdict != std::string::npos && verdict < html.find("<h2>") && verdict < html.find("<img"),
        name + ": the verdict comes before every section and plot");

  std::string probe_html = html;
  probe_html.insert(probe_html.rfind("</body>"), kProbe);
  const fs::path probe = report_dir / "probe.html";
  std::ofstream(probe) << probe_html;
  const std::string flags = " --headless --no-sandbox --disable-gpu --user-data-dir='" + (report_dir / "chromium-profile").string() + "'";
  std::string dom;
  check(run(chromium + flags + " --virtual-time-budget=10000 --dump-dom 'file://" + probe.string() + "'", &dom) == 0,
        name + ": chromium --dump-dom ran");
  std::smatch m;
  if (!std::regex_search(dom, m, std::regex("<pre id=\"probe\">IMAGES (.*?) END</pre>"))) {
    check(false, name + ": the page loaded (probe output in the DOM)");
    return;
  }
  const std::string list = m[1];
  std::size_t images = 0;
  const std::regex item("(\\d+)x(\\d+):(-?\\d+)");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), item); it != std::sregex_iterator(); ++it) {
    ++images;
    const long w = std::stol((*it)[1]), h = std::stol((*it)[2]), ink = std::stol((*it)[3]);
    check(w >= 300 && h >= 200, name + ": plot " + std::to_string(images) + " decodes (" + it->str() + ")");
    check(ink > w * h / 200, name + ": plot " + std::to_string(images) + " is not blank (" + it->str() + ")");
  }
  check(images == plots, name + ": " + std::to_string(plots) + " plots embedded, found " + std::to_string(images));

  const fs::path shot = report_dir / "screenshot.png";
  run(chromium + flags + " --hide-scrollbars --screenshot='" + shot.string() + "' --window-size=1200,3000 'file://" + page.string() + "'");
  long total = 0;
  const long ink = ink_in_png(shot, &total);
  check(ink > 0 && total == 1200L * 3000L, name + ": screenshot written (" + shot.string() + ")");
  check(ink > total / 500, name + ": screenshot not blank (" + std::to_string(ink) + " of " + std::to_string(total) + " pixels)");
  std::cout << name << ": " << images << " plots decoded, screenshot " << shot.string() << " (" << ink << " of " << total
            << " pixels not white)\n";
}

// Two loads per log, so the gap's fit has something to explain.
fs::path write_log(const fs::path& dir, const std::string& name, int rows, double kp2) {
  const fs::path p = dir / name;
  std::ofstream f(p);
  f << "t[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
  for (int k = 0; k < rows; ++k) {
    char b[160];
    std::snprintf(b, sizeof b, "%.3f,35,%.4e,33.1,1.9,171.1,1678\n", 0.01 * k, k < rows / 2 ? 4.41e-8 : kp2);
    f << b;
  }
  return p;
}

}  // namespace

int main() {
  const std::string chromium = chromium_binary();
  if (chromium.empty()) {
    std::cout << "chromium not installed (apt-get install chromium): skipped\n";
    return 77;
  }
  if (run("command -v gnuplot >/dev/null") != 0) {
    std::cerr << "gnuplot not installed: the reports would have no plots\n";
    return 1;
  }
  const fs::path dir = fs::temp_directory_path() / ("hstmon_report_html_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cli = std::string("'") + HSTMON_CLI + "'";

  const fs::path fit = write_log(dir, "fit_log.csv", 400, 3e-8), chk = write_log(dir, "check_log.csv", 300, 6e-8);
  const fs::path gap_dir = dir / "gap";
  check(run(cli + " gap --fit '" + fit.string() + "' --check '" + chk.string() + "' --effects coulomb_friction --report '" +
            gap_dir.string() + "'") == 0,
        "hstmon gap --report");
  check_page(chromium, gap_dir, 3, "gap");

  const fs::path replay_dir = dir / "replay";
  check(run(cli + " replay '" + HSTMON_SOURCE_DIR + "/examples/prv_blockage_das.csv' --report '" + replay_dir.string() + "'") == 0,
        "hstmon replay --report");
  check_page(chromium, replay_dir, 1, "replay");

  // A circuit's replay: the same page, the circuit's sensors (paper.json: four, its Dm fault).
  const fs::path circuit_dir = dir / "replay_circuit";
  check(run(cli + " replay --circuit '" + HSTMON_SOURCE_DIR + "/examples/circuits/paper.json' '" + HSTMON_SOURCE_DIR +
            "/examples/circuits/paper_dm_fault.csv' --report '" + circuit_dir.string() + "'") == 0,
        "hstmon replay --circuit --report");
  check_page(chromium, circuit_dir, 1, "replay --circuit");

  const fs::path id_dir = dir / "identify";
  check(run(cli + " identify '" + HSTMON_SOURCE_DIR + "/examples/prv_staircase_das.csv' --assume-steady --out '" +
            (dir / "identified.json").string() + "' --report '" + id_dir.string() + "'") == 0,
        "hstmon identify --report");
  check_page(chromium, id_dir, 1, "identify");

  if (failures > 0) return 1;
  // The pages stay for a look (HSTMON_KEEP_REPORTS=1), else the test leaves nothing behind.
  if (std::getenv("HSTMON_KEEP_REPORTS") == nullptr) {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::cout << "ok\n";
  return 0;
}
