// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/pictures/svg_text.h"

#include <QFont>
#include <QFontInfo>
#include <QFontMetricsF>
#include <QHash>
#include <QImage>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <cmath>
#include <vector>

namespace grazelab::pictures {
namespace {

// the attributes that style one run; the rest (x, y, xml:space) belong to the line
bool isRunStyle(QStringView name) {
  return name != QLatin1String("x") && name != QLatin1String("y") && name != QLatin1String("space");
}

struct Run {
  QXmlStreamAttributes attributes;
  QString text;
  double x = 0;
  double y = 0;
  double width = 0;  // as Qt laid it out
};

// The font of a run as Qt wrote it: its size is in the picture's units, read here as pixels
// (a device of 72 dpi makes a point one pixel, fractional sizes included).
QFont runFont(const QXmlStreamAttributes& attributes) {
  QFont font(attributes.value(QLatin1String("font-family")).toString());
  font.setPointSizeF(std::max(0.1, attributes.value(QLatin1String("font-size")).toDouble()));
  const int weight = attributes.value(QLatin1String("font-weight")).toInt();
  if (weight > 0) font.setWeight(QFont::Weight(weight));
  font.setItalic(attributes.value(QLatin1String("font-style")) != QLatin1String("normal") &&
                 !attributes.value(QLatin1String("font-style")).isEmpty());
  return font;
}

double advance(const QXmlStreamAttributes& attributes, const QString& text) {
  static QImage device = [] {
    QImage image(1, 1, QImage::Format_ARGB32);
    image.setDotsPerMeterX(qRound(72 / 0.0254));
    image.setDotsPerMeterY(qRound(72 / 0.0254));
    return image;
  }();
  return QFontMetricsF(runFont(attributes), &device).horizontalAdvance(text);
}

// "Sans Serif" -> "'DejaVu Sans', 'Sans Serif', sans-serif": the family Qt drew with first
QString familyList(const QString& asked) {
  static QHash<QString, QString> lists;
  auto found = lists.constFind(asked);
  if (found != lists.constEnd()) return *found;
  const QFontInfo drawn{QFont(asked)};
  QStringList families;
  if (drawn.family() != asked) families << QStringLiteral("'%1'").arg(drawn.family());
  families << QStringLiteral("'%1'").arg(asked);
  families << (drawn.fixedPitch() ? QStringLiteral("monospace") : QStringLiteral("sans-serif"));
  return lists[asked] = families.join(QStringLiteral(", "));
}

// by qualified name, as read (a namespaced write would invent prefixes for xml: and xlink:);
// each font family made a list; `keep` chooses which
template <typename Keep>
void writeAttributes(QXmlStreamWriter& out, const QXmlStreamAttributes& attributes, Keep keep) {
  for (const QXmlStreamAttribute& attribute : attributes) {
    if (!keep(attribute.name())) continue;
    const QString name = attribute.qualifiedName().toString();
    const QString value = attribute.value().toString();
    out.writeAttribute(name, name == QLatin1String("font-family") ? familyList(value) : value);
  }
}

bool any(QStringView) { return true; }

// a run that starts where the last one ended, on its line (Qt splits a line at each change of
// script or format; its layout leaves no gap there)
bool continues(const Run& last, const Run& next) {
  constexpr double tolerance = 0.75;  // px: kerning across the split, rounding of the x written
  return std::abs(next.y - last.y) < 1e-3 && std::abs(next.x - (last.x + last.width)) < tolerance;
}

void writeLine(QXmlStreamWriter& out, const std::vector<Run>& line) {
  const Run& first = line.front();
  const double length = line.back().x + line.back().width - first.x;
  out.writeStartElement(QStringLiteral("text"));
  if (line.size() == 1) {
    writeAttributes(out, first.attributes, any);
  } else {
    writeAttributes(out, first.attributes, [](QStringView name) { return !isRunStyle(name); });
  }
  // drawn as long as on screen whatever font the reader has: no run overruns the next label
  if (length > 0) {
    out.writeAttribute(QStringLiteral("textLength"), QString::number(length, 'g', 6));
    out.writeAttribute(QStringLiteral("lengthAdjust"), QStringLiteral("spacingAndGlyphs"));
  }
  if (line.size() == 1) {
    out.writeCharacters(first.text);
  } else {
    for (const Run& run : line) {
      out.writeStartElement(QStringLiteral("tspan"));
      writeAttributes(out, run.attributes, isRunStyle);
      out.writeCharacters(run.text);
      out.writeEndElement();
    }
  }
  out.writeEndElement();
}

}  // namespace

QByteArray wholeSvgText(const QByteArray& svg) {
  QXmlStreamReader in(svg);
  QByteArray result;
  QXmlStreamWriter out(&result);
  std::vector<Run> line;
  const auto endLine = [&] {
    if (!line.empty()) writeLine(out, line);
    line.clear();
  };
  while (!in.atEnd()) {
    in.readNext();
    if (in.isStartElement() && in.name() == QLatin1String("text")) {
      Run run;
      run.attributes = in.attributes();
      run.x = run.attributes.value(QLatin1String("x")).toDouble();
      run.y = run.attributes.value(QLatin1String("y")).toDouble();
      // Qt's runs hold characters only; readElementText keeps them as written (xml:space)
      run.text = in.readElementText(QXmlStreamReader::IncludeChildElements);
      run.width = advance(run.attributes, run.text);
      if (!line.empty() && !continues(line.back(), run)) endLine();
      line.push_back(std::move(run));
      continue;
    }
    // the line breaks between one group's runs
    if (in.isWhitespace() && !line.empty()) continue;
    endLine();
    if (in.isStartElement()) {
      out.writeStartElement(in.qualifiedName().toString());
      for (const QXmlStreamNamespaceDeclaration& declaration : in.namespaceDeclarations()) {
        const QString prefix = declaration.prefix().toString();
        out.writeAttribute(prefix.isEmpty() ? QStringLiteral("xmlns") : QStringLiteral("xmlns:") + prefix,
                           declaration.namespaceUri().toString());
      }
      writeAttributes(out, in.attributes(), any);
    } else {
      out.writeCurrentToken(in);
    }
  }
  // what cannot be read is left as Qt wrote it
  return in.hasError() ? svg : result;
}

}  // namespace grazelab::pictures
