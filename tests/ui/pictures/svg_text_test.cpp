// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The text of an SVG picture as any reader draws it (issue 48, item 6): sized as on screen, each
// line one <text> (Qt wrote "GLO(", "λ), " and "max" apart, and a reader with other fonts drew
// them apart or over each other), a family list that ends in a generic family.
#include "ui/pictures/picture_file.h"
#include "ui/pictures/svg_text.h"

#include <QFontInfo>
#include <QPainter>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextLayout>
#include <QXmlStreamReader>
#include <QtTest>

namespace grazelab::pictures {
namespace {

struct SvgText {
  QString text;  // its characters, those of its tspans joined
  QString fontSize;
  QString fontFamily;
  double textLength = 0;
};

QList<SvgText> readTexts(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  QXmlStreamReader xml(&file);
  QList<SvgText> texts;
  while (!xml.atEnd()) {
    if (xml.readNext() != QXmlStreamReader::StartElement || xml.name() != QLatin1String("text")) continue;
    SvgText text;
    text.textLength = xml.attributes().value(QLatin1String("textLength")).toDouble();
    text.fontSize = xml.attributes().value(QLatin1String("font-size")).toString();
    text.fontFamily = xml.attributes().value(QLatin1String("font-family")).toString();
    while (!(xml.isEndElement() && xml.name() == QLatin1String("text")) && !xml.atEnd()) {
      xml.readNext();
      if (xml.isStartElement() && text.fontSize.isEmpty()) {
        text.fontSize = xml.attributes().value(QLatin1String("font-size")).toString();
        text.fontFamily = xml.attributes().value(QLatin1String("font-family")).toString();
      }
      if (xml.isCharacters()) text.text += xml.text();
    }
    texts.append(text);
  }
  if (xml.hasError()) qWarning() << path << xml.errorString();
  return texts;
}

}  // namespace

class SvgTextTest : public QObject {
  Q_OBJECT

 private slots:
  void aLineOfScriptsAndFormatsIsOneTextSizedAsOnScreen() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("line.svg"));
    QFont font(QStringLiteral("Sans Serif"));
    font.setPointSizeF(9);
    const QString title = QStringLiteral("Lemma 2.1: top of GLO(λ), ");
    const QString rest = QStringLiteral("max u₂ / d");
    double lineWidth = 0;
    QString error;
    const bool written = writeSvg(
        path, QSize(400, 100),
        [&](QPainter& painter) {
          // Latin, Greek, then a change of weight on one line, as a chart's title is drawn
          // (a QTextDocument); a second label far to the right stays its own text
          QTextDocument document;
          document.setDocumentMargin(0);
          document.setDefaultFont(font);
          document.setHtml(QStringLiteral("<b>%1</b>%2").arg(title, rest));
          document.drawContents(&painter);
          lineWidth = document.firstBlock().layout()->lineAt(0).naturalTextWidth();
          painter.setFont(font);
          painter.drawText(QPointF(330, 30), QStringLiteral("apart"));
        },
        PictureMetadata{QStringLiteral("line"), QStringLiteral("Test"), "{}"}, &error, 96);
    QVERIFY2(written, qPrintable(error));

    const QList<SvgText> texts = readTexts(path);
    QCOMPARE(texts.size(), 2);
    QCOMPARE(texts[0].text, title + rest);
    QCOMPARE(texts[1].text, QStringLiteral("apart"));
    // 9 pt at 96 dpi are 12 px: Qt's default resolution wrote "9", three quarters of the
    // screen's size, in a picture whose units are the screen's pixels
    QCOMPARE(texts[0].fontSize.toDouble(), 12.0);
    // as long as it was laid out, whatever the reader's fonts
    QVERIFY2(std::abs(texts[0].textLength - lineWidth) < 1.0,
             qPrintable(QStringLiteral("%1 against %2").arg(texts[0].textLength).arg(lineWidth)));
    // the family Qt drew with first, a generic family last: "Sans Serif" is Qt's alias, a
    // browser knows no such family and fell back to a serif font
    const QString drawnFamily = QFontInfo(font).family();
    QVERIFY2(texts[0].fontFamily.startsWith(QStringLiteral("'%1'").arg(drawnFamily)), qPrintable(texts[0].fontFamily));
    QVERIFY2(texts[0].fontFamily.endsWith(QStringLiteral("sans-serif")), qPrintable(texts[0].fontFamily));
  }

  void whatCannotBeReadIsLeftAsItWas() {
    // a rewrite that fails part-way must not cut the picture short
    const QByteArray broken = "<svg><g><text x=\"1\" y=\"2\">a</text><text x=\"9\" y=\"2\">b</g></svg>";
    QCOMPARE(wholeSvgText(broken), broken);
  }
};

}  // namespace grazelab::pictures

QTEST_MAIN(grazelab::pictures::SvgTextTest)
#include "svg_text_test.moc"
