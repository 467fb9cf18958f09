#pragma once

#include "raylab/core/Image.h"

#include <QImage>
#include <QWidget>

namespace raylab::app {

/**
 * \brief A rendered image, zoomed with nearest-neighbour sampling so single pixels stay
 * visible: the hovered pixel is reported (for its value), a click chooses a pixel (to
 * trace it), and the chosen pixel is marked with a frame.
 *
 * Zoom is either "fit" (the largest scale that shows the whole image, fractional) or a
 * whole number of screen pixels per image pixel (1 to 32); the wheel with Ctrl zooms,
 * keeping the pixel under the cursor where it is.
 * Put it in a QScrollArea with widgetResizable(true).
 */
class ImageView : public QWidget {
  Q_OBJECT

 public:
  explicit ImageView(QWidget* parent = nullptr);

  /// Shows `image` (linear radiance; drawn through the sRGB curve, clamped).
  void setImage(const FloatImage& image);
  /// Shows `image` with its 8-bit `picture` already made by toPicture(image) (e.g. on a
  /// render thread, so the UI thread only copies).
  void setImage(const FloatImage& image, const QImage& picture);
  /// Forgets the image (an empty view with `hint` written in it).
  void clear(const QString& hint);
  const FloatImage& image() const { return m_image; }
  /// The 8-bit picture drawn (what a PNG save writes).
  const QImage& picture() const { return m_picture; }

  /// Zoom: 0 = fit to the view, else screen pixels per image pixel.
  void setZoom(int zoom);
  int zoom() const { return m_zoom; }
  /// Screen pixels per image pixel as drawn now.
  double scale() const;
  /// One step in or out, keeping the image point under the cursor where it is (else the
  /// one in the middle of what is on screen): Ctrl++, Ctrl+-, the buttons.
  void zoomIn();
  void zoomOut();
  /// One step in or out keeping the image point at widget position `anchor` under it
  /// (scrolling the QScrollArea the view is in).
  void zoomInAt(const QPoint& anchor);
  void zoomOutAt(const QPoint& anchor);

  /// Marks pixel (x, y); (-1, -1) removes the mark.
  void setMarkedPixel(int x, int y);
  QPoint markedPixel() const { return m_marked; }
  /// The image pixel under widget position `position`, (-1, -1) outside the image.
  QPoint pixelAt(const QPoint& position) const;
  /// Where image pixel (x, y)'s top-left corner is drawn, in widget coordinates.
  QPointF positionOf(int x, int y) const;

  QSize sizeHint() const override;

 signals:
  /// The pixel under the cursor changed ((-1, -1): none).
  void pixelHovered(int x, int y);
  /// A pixel was clicked.
  void pixelClicked(int x, int y);
  void zoomChanged(int zoom);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  /// The image's rectangle on the widget.
  QRectF imageRect() const;
  void updateSize();
  /// Where zoomIn and zoomOut anchor: the cursor over the view, else its visible middle.
  QPoint zoomAnchor() const;
  /// Zooms to `zoom`, scrolling so that the image point at `anchor` stays where it is.
  void zoomAt(int zoom, const QPoint& anchor);

  FloatImage m_image;
  QImage m_picture;
  QString m_hint;
  int m_zoom = 0;
  QPoint m_marked{-1, -1};
  QPoint m_hovered{-1, -1};
};

/// The 8-bit picture an ImageView draws of `image`: the sRGB curve, clamped. Safe on any
/// thread.
QImage toPicture(const FloatImage& image);

/// "R 0.512 G 0.031 B 0.027 (sRGB 190, 49, 46)": a pixel's linear value and its 8-bit colour.
QString describePixel(const FloatImage& image, int x, int y);

}  // namespace raylab::app
