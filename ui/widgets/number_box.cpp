// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/widgets/number_box.h"

#include <QKeyEvent>
#include <QRegularExpression>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace grazelab::ui {
namespace {

/// Texts that can still become a number as typing goes on ("-", "1.", "2e", "2e-").
bool couldBecomeNumber(const QString& text) {
  static const QRegularExpression partial(
      QStringLiteral("^\\s*[+-]?(\\d*\\.?\\d*)([eE][+-]?\\d*)?\\s*$"));
  return partial.match(text).hasMatch();
}

QString normalised(QString text) {
  text.replace(QChar(0x2212), QLatin1Char('-'));  // the minus sign a copied formula carries
  return text.trimmed();
}

}  // namespace

QString shortestText(double value) {
  // a whole number as one (1000000, not 1e+06) while every digit of it is exact
  if (value == std::floor(value) && std::abs(value) < 1e15) return QString::number(value, 'f', 0);
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (error != std::errc()) return QString::number(value, 'g', 17);
  return QString::fromLatin1(buffer, int(end - buffer));
}

std::optional<double> readNumber(const QString& typed) {
  const QByteArray text = normalised(typed).toLatin1();
  const char* begin = text.constData();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars takes no plus sign
  double value = 0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (begin == end || stop != end || error != std::errc()) return std::nullopt;
  return value;
}

NumberBox::NumberBox(QString name, double minimum, double maximum, bool whole, QWidget* parent)
    : QDoubleSpinBox(parent), m_name(std::move(name)), m_whole(whole) {
  // the most Qt allows: QDoubleSpinBox rounds every value to its decimals, and must not
  setDecimals(std::numeric_limits<double>::max_exponent10 + std::numeric_limits<double>::digits10);
  setRange(minimum, maximum);
  setKeyboardTracking(false);
  setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
}

QString NumberBox::textFromValue(double value) const { return shortestText(value); }

double NumberBox::valueFromText(const QString& text) const {
  return readNumber(text).value_or(value());
}

void NumberBox::stepBy(int steps) {
  const double scale = std::pow(10.0, m_stepDecimals);
  const double stepped = std::round((value() + steps * singleStep()) * scale) / scale;
  setValue(std::clamp(stepped, minimum(), maximum()));
}

QString NumberBox::refusal(const QString& text) const {
  const std::optional<double> number = readNumber(text);
  if (!number || !std::isfinite(*number)) {
    return tr("%1: \"%2\" is not a number; kept %3.").arg(m_name, text.trimmed(), shortestText(value()));
  }
  if (m_whole && *number != std::floor(*number)) {
    return tr("%1 is a whole number: %2 refused; kept %3.").arg(m_name, text.trimmed(), shortestText(value()));
  }
  if (*number < minimum() || *number > maximum()) {
    return tr("%1 must lie in [%2, %3]: %4 refused; kept %5.")
        .arg(m_name, shortestText(minimum()), shortestText(maximum()), text.trimmed(),
             shortestText(value()));
  }
  return {};
}

QValidator::State NumberBox::validate(QString& text, int&) const {
  if (!couldBecomeNumber(normalised(text))) return QValidator::Invalid;
  // anything else may still be on its way to a good value: refused, if at all, when the edit ends
  return refusal(text).isEmpty() ? QValidator::Acceptable : QValidator::Intermediate;
}

void NumberBox::fixup(QString& text) const {
  // called when an edit ends on a text validate() did not accept: the spin box then goes back
  // to its previous value; say why, so that nothing changes silently
  if (const QString reason = refusal(text); !reason.isEmpty()) emit refused(reason);
}

bool NumberBox::event(QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride) {
    const auto* key = static_cast<QKeyEvent*>(event);
    const Qt::KeyboardModifiers modifiers = key->modifiers() & ~Qt::KeypadModifier;
    // a line edit claims Ctrl+E (end of line), Space and PageUp/PageDown for itself; none of them
    // helps to type a number, and the window's shortcuts for them must work from here too
    const bool editing = key->matches(QKeySequence::Copy) || key->matches(QKeySequence::Cut) ||
                         key->matches(QKeySequence::Paste) || key->matches(QKeySequence::Undo) ||
                         key->matches(QKeySequence::Redo) || key->matches(QKeySequence::SelectAll);
    const bool toWindow =
        (modifiers == Qt::ControlModifier && key->key() >= Qt::Key_A && key->key() <= Qt::Key_Z &&
         !editing) ||
        (modifiers == Qt::NoModifier &&
         (key->key() == Qt::Key_Space || key->key() == Qt::Key_PageUp ||
          key->key() == Qt::Key_PageDown ||
          // the window's letter keys (W: the whole run, R: reset the views) are in no number
          key->key() == Qt::Key_W || key->key() == Qt::Key_R));
    if (toWindow) {
      event->ignore();
      return true;
    }
  }
  return QDoubleSpinBox::event(event);
}

}  // namespace grazelab::ui
