// The report's closing sections: the list of files, and the notes on figures not drawn.
#include <sstream>

#include "report/sections.hpp"

namespace gyrores::report {

std::string files_section(const figure_set& figs) {
  std::ostringstream md;
  md << "## Files\n\n";
  for (const auto& [stem, have] : figs.drawn) {
    md << "- " << stem << ": ";
    if (have.png) md << "[png](figures/" << stem << ".png) ";
    if (have.svg) md << "[svg](figures/" << stem << ".svg) ";
    if (have.pdf) md << "[pdf](figures/" << stem << ".pdf) ";
    md << "[data](figures/" << stem << ".dat) [script](figures/" << stem << ".gp)\n";
  }
  md << "- [pareto-front.csv](pareto-front.csv)\n\n"
     << "Restyle a figure: edit its `.gp` file, then `cd figures && gnuplot -e \"outfile='NAME.svg'\" NAME.gp` (or `NAME.pdf`: "
        "the PDF is the figure's size at 100 pixels per inch, fonts in points).\n\n";
  if (!figs.notes.empty()) {
    md << "## Notes\n\n";
    for (auto& n : figs.notes) md << "- " << n << "\n";
    md << "\n";
  }
  return md.str();
}

}  // namespace gyrores::report

