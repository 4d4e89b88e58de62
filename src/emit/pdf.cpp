// pdflatex on a document in a fresh temporary directory, and what its log says.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kinergy/common/process.hpp"
#include "kinergy/emit/derive.hpp"

namespace kinergy::emit {

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

}  // namespace

bool have_pdflatex() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) continue;
    fs::path p = fs::path(dir) / "pdflatex";
    if (access(p.c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string pdflatex_error(const std::string& log, int rc) {
  // a missing package names its Debian package
  if (log.find("`tikz.sty' not found") != std::string::npos)
    return "pdflatex cannot find TikZ (tikz.sty), which draws the figures: install Debian's texlive-pictures (bash .ci/setup --deps)";
  // the first error of the log: "! Undefined control sequence." and the line after it
  auto p = log.find("\n! ");
  std::string first = p == std::string::npos ? "exit status " + std::to_string(rc) : log.substr(p + 1, 300);
  for (char& c : first)
    if (c == '\n') c = ' ';
  return "pdflatex failed: " + first;
}

PdfRun run_pdflatex(const std::string& tex, const std::string& pdf_path) {
  PdfRun r;
  if (!have_pdflatex()) {
    r.error = "pdflatex is not installed (Debian: apt-get install texlive-latex-base texlive-latex-recommended texlive-pictures)";
    return r;
  }
  std::string templ = (fs::temp_directory_path() / "kinergy-tex-XXXXXX").string();
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!mkdtemp(buf.data())) {
    r.error = "cannot make a temporary directory";
    return r;
  }
  fs::path dir(buf.data());
  {
    std::ofstream out(dir / "derivation.tex", std::ios::binary);
    out << tex;
  }
  int rc = run_program(dir, {"pdflatex", "-interaction=nonstopmode", "-halt-on-error", "derivation.tex"}, dir / "pdflatex.out");
  r.ran = rc >= 0 && rc != 127;
  r.log = read_file(dir / "derivation.log");
  r.output = read_file(dir / "pdflatex.out");
  r.ok = rc == 0 && fs::exists(dir / "derivation.pdf");
  if (!r.ran) {
    r.error = "pdflatex could not be started";
  } else if (!r.ok) {
    r.error = pdflatex_error(r.log, rc);
  } else if (!pdf_path.empty()) {
    std::error_code ec;
    fs::copy_file(dir / "derivation.pdf", pdf_path, fs::copy_options::overwrite_existing, ec);
    if (ec) {
      r.ok = false;
      r.error = "cannot write the PDF: " + ec.message();
    }
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  return r;
}

std::vector<double> overfull_boxes(const std::string& log) {
  // "Overfull \hbox (12.34pt too wide) in paragraph at lines 5--6"
  std::vector<double> out;
  const std::string key = "Overfull \\hbox (";
  for (std::size_t p = log.find(key); p != std::string::npos; p = log.find(key, p + 1)) {
    std::size_t s = p + key.size();
    std::size_t e = log.find("pt too wide", s);
    if (e == std::string::npos) continue;
    try {
      out.push_back(std::stod(log.substr(s, e - s)));
    } catch (const std::exception&) {
      out.push_back(1e9);
    }
  }
  return out;
}

}  // namespace kinergy::emit
