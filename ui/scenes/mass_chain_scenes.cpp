// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/scenes/mass_chain_scenes.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

#include "core/model/chain_design.h"
#include "core/model/model.h"
#include "ui/widgets/chain_editor.h"

namespace grazelab::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("grazelab::ui::MassChainScenes", text);
}

QString number(double value, int digits = 4) { return QString::number(value, 'g', digits); }

QString list(const std::vector<double>& values, int digits = 4) {
  QStringList parts;
  for (double value : values) parts.append(number(value, digits));
  return parts.join(QStringLiteral(", "));
}

// The modes as a table: each one's frequency, its harmonic number (w_j = n_j w0 on a
// commensurate chain; the nearest ratio's, marked ~, on another) and its GLOM's shape: the
// displacements over d of the mode alone with its top on the stop (a mode with a node at the
// stopped mass has none: it never reaches the stop)
QString modesTable(const core::ChainModes& modes, const core::SpectrumRatios& ratios, int stopped) {
  const Eigen::Index n = modes.omega.size();
  QString html = QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\"><tr><th align=\"left\">%1</th>"
                                "<th align=\"right\">&nbsp;ω</th><th align=\"right\">&nbsp;n</th>"
                                "<th align=\"left\">&nbsp;%2</th></tr>")
                     .arg(tr("mode"), tr("shape u / d of its GLOM"));
  for (Eigen::Index j = 0; j < n; ++j) {
    QString harmonic;
    if (std::size_t(j) < ratios.harmonics.size()) {
      harmonic = (ratios.commensurate ? QString() : QStringLiteral("~")) + QString::number(ratios.harmonics[std::size_t(j)]);
    }
    QString shape = tr("node at mass %1: no GLOM").arg(stopped);
    if (!modes.nodeAtStop[std::size_t(j)]) {
      QStringList parts;
      for (Eigen::Index i = 0; i < n; ++i) parts.append(number(modes.P(i, j) / modes.P(stopped - 1, j), 3));
      shape = parts.join(QStringLiteral(", "));
    }
    html += QStringLiteral("<tr><td>%1</td><td align=\"right\">&nbsp;%2</td><td align=\"right\">&nbsp;%3</td>"
                           "<td>&nbsp;%4</td></tr>")
                .arg(j + 1)
                .arg(number(modes.omega[j]), harmonic, shape);
  }
  return html + QStringLiteral("</table>");
}

}  // namespace

ChainChoice chooseChain(const MassChainParams& given, double gap, std::stop_token stop) {
  ChainChoice choice;
  core::MassChain chain{given.masses, given.springs, given.rightSpring, given.stopMass, gap};
  if (!given.harmonics.empty()) {
    core::DesignChoice design = core::chooseDesign(given.masses, given.springs.front(), given.rightSpring,
                                                   given.harmonics, std::max(given.designBranch, 1), stop);
    const core::ChainDesigns& designs = design.designs;
    switch (design.problem) {
      case core::DesignChoiceProblem::None:
        break;
      case core::DesignChoiceProblem::NoSuchDesign:
        design.number = int(designs.designs.size());  // the last there is (the editor offers only those)
        design.problem = core::DesignChoiceProblem::None;
        break;
      case core::DesignChoiceProblem::NoPositiveDesign:
        // a wall the design keeps as given can be what rules every design out: named then
        choice.problem =
            given.rightSpring > 0
                ? tr("No chain with these masses and this right wall (k = %3) has the frequencies in "
                     "the ratio %1: every one of the %2 solutions of the design equations is complex "
                     "or has a spring ≤ 0. Change the masses or the wall's spring, or pick another "
                     "resonance.")
                      .arg(resonanceName(given.harmonics))
                      .arg(designs.paths)
                      .arg(number(given.rightSpring, 4))
                : tr("No chain with these masses has the frequencies in the ratio %1: every one of "
                     "the %2 solutions of the design equations is complex or has a spring ≤ 0. "
                     "Change the masses, or pick another resonance.")
                      .arg(resonanceName(given.harmonics))
                      .arg(designs.paths);
        return choice;
      case core::DesignChoiceProblem::Incomplete:
        choice.problem =
            tr("The design of %1 could not follow every solution, so no list of designs can be "
               "promised: change the masses slightly.")
                .arg(resonanceName(given.harmonics));
        return choice;
      case core::DesignChoiceProblem::Stopped:
        return choice;
      case core::DesignChoiceProblem::BadRequest:
        choice.problem = tr("The resonance %1 cannot be designed for %2 masses.")
                             .arg(resonanceName(given.harmonics))
                             .arg(given.masses.size());
        return choice;
    }
    choice.designs = int(designs.designs.size());
    chain.springs = design.chosen().springs;
    choice.design = std::move(design);
  }
  if (const auto problems = core::validate(chain); !problems.empty()) {
    choice.problem = QString::fromStdString(core::describe(problems));
    return choice;
  }
  choice.chain = chain;
  return choice;
}

QString chainSummaryOf(const core::MassChain& chain, const MassChainParams& given, int designs,
                       const core::ChainModes& modes, const core::SpectrumRatios& ratios, const QString& more) {
  const std::vector<double> omega(modes.omega.data(), modes.omega.data() + modes.omega.size());
  const bool noneOffered = ChainEditor::resonancesFor(chain.size()).size() == 1;
  QString text = given.harmonics.empty() ? (noneOffered ? tr("Springs k = %1 (as given: no resonance is offered for %2).")
                                                              .arg(list(chain.springs),
                                                                   chain.size() == 1 ? tr("one mass")
                                                                                     : tr("%1 masses").arg(chain.size()))
                                                        : tr("Springs k = %1 (as given).").arg(list(chain.springs)))
                                         : tr("Springs designed for %1 (design %2 of %3): k = %4.")
                                               .arg(resonanceName(given.harmonics))
                                               .arg(std::clamp(given.designBranch, 1, designs))
                                               .arg(designs)
                                               .arg(list(chain.springs));
  if (chain.rightSpring > 0) text += QLatin1Char(' ') + tr("Right wall: k = %1.").arg(number(chain.rightSpring, 4));
  text += QLatin1Char(' ') + tr("Frequencies ω = %1 (fastest first).").arg(list(omega));
  QStringList harmonics;
  for (int n : ratios.harmonics) harmonics.append(QString::number(n));
  if (ratios.commensurate) {
    text += QLatin1Char(' ') +
            tr("In the ratio %1 × ω₀ (ω₀ = %2, off by %3): every free motion repeats after "
               "T = 2π/ω₀ = %4.")
                .arg(harmonics.join(QStringLiteral(" : ")), number(ratios.omega0, 6),
                     number(ratios.detuning, 2), number(2 * M_PI / ratios.omega0, 6));
  } else if (!ratios.harmonics.empty()) {
    text += QLatin1Char(' ') +
            tr("Not commensurate: nearest %1, detuned by %2 %; no common period.")
                .arg(harmonics.join(QStringLiteral(" : ")), number(100 * ratios.detuning, 2));
  } else {
    text += QLatin1Char(' ') + tr("Not commensurate: no common period.");
  }
  if (!more.isEmpty()) text += QLatin1Char(' ') + more;
  return text + modesTable(modes, ratios, chain.stopped());
}

SceneJob refusedChainJob(const QString& why) {
  SceneJob job;
  job.message = why;
  job.chain.summary = why;
  job.chain.refused = true;
  return job;
}

SceneJob refusedStartJob(const QString& why) {
  SceneJob job;
  job.message = why;
  return job;
}

QString gloStartProblemInWords(core::GloStartProblem problem) {
  return problem == core::GloStartProblem::WeightOnNode
             ? tr("A weight is on a mode that does not move the stopped mass: it has no grazing "
                  "orbit")
             : tr("The weights of the grazing orbit must be finite and sum to 1");
}

}  // namespace grazelab::ui
