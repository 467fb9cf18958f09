#include "ImageView.h"

#include <QCursor>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollArea>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace raylab::app {

namespace {
constexpr int kMaxZoom = 32;
}  // namespace

QString describePixel(const FloatImage& image, int x, int y) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return {};
  const glm::vec3 v = image.pixels[std::size_t(y) * image.width + x];
  return QObject::tr("R %1  G %2  B %3 (sRGB %4, %5, %6)")
      .arg(double(v.x), 0, 'f', 3)
      .arg(double(v.y), 0, 'f', 3)
      .arg(double(v.z), 0, 'f', 3)
      .arg(imageio::toSrgb8(v.x))
      .arg(imageio::toSrgb8(v.y))
      .arg(imageio::toSrgb8(v.z));
}

ImageView::ImageView(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setCursor(Qt::CrossCursor);
  setBackgroundRole(QPalette::Dark);
  setAutoFillBackground(true);
  setToolTip(tr("Click a pixel to trace its ray tree in the 3D view; Ctrl+wheel zooms"));
}

QImage toPicture(const FloatImage& image) {
  const SrgbImage srgb = imageio::toSrgb(image);
  QImage picture(srgb.width, srgb.height, QImage::Format_RGB888);
  for (int y = 0; y < srgb.height; ++y)
    std::copy_n(srgb.rgb.begin() + std::ptrdiff_t(y) * srgb.width * 3, srgb.width * 3,
                picture.scanLine(y));
  return picture;
}

void ImageView::setImage(const FloatImage& image) { setImage(image, toPicture(image)); }

void ImageView::setImage(const FloatImage& image, const QImage& picture) {
  const bool resized = image.width != m_image.width || image.height != m_image.height;
  m_image = image;
  m_picture = picture;
  if (resized) updateSize();
  update();
}

void ImageView::clear(const QString& hint) {
  m_image = FloatImage();
  m_picture = QImage();
  m_hint = hint;
  m_marked = {-1, -1};
  updateSize();
  update();
}

void ImageView::setZoom(int zoom) {
  zoom = std::clamp(zoom, 0, kMaxZoom);
  if (zoom == m_zoom) return;
  m_zoom = zoom;
  updateSize();
  update();
  emit zoomChanged(m_zoom);
}

double ImageView::scale() const {
  if (m_picture.isNull()) return 1.0;
  if (m_zoom > 0) return m_zoom;
  return std::max(
      1e-3, std::min(double(width()) / m_picture.width(), double(height()) / m_picture.height()));
}

void ImageView::zoomIn() { zoomInAt(zoomAnchor()); }

void ImageView::zoomOut() { zoomOutAt(zoomAnchor()); }

void ImageView::zoomInAt(const QPoint& anchor) {
  zoomAt(m_zoom == 0 ? std::max(1, int(std::floor(scale())) + 1) : std::min(kMaxZoom, m_zoom * 2),
         anchor);
}

void ImageView::zoomOutAt(const QPoint& anchor) {
  if (m_zoom == 0) return;
  zoomAt(m_zoom / 2, anchor);  // 1 -> 0: fit
}

QPoint ImageView::zoomAnchor() const {
  // The cursor when it is over the part of the image on screen (Ctrl++ with the mouse
  // over it), else the middle of that part.
  const QRect visible = visibleRegion().boundingRect();
  const QPoint cursor = mapFromGlobal(QCursor::pos());
  if (visible.contains(cursor)) return cursor;
  return visible.isEmpty() ? rect().center() : visible.center();
}

void ImageView::zoomAt(int zoom, const QPoint& anchor) {
  // The image point under `anchor` stays under it: where it is in the image (in image
  // pixels) and on the screen (in the scroll area's viewport) before the zoom...
  const double before = scale();
  const QPointF point = (QPointF(anchor) - imageRect().topLeft()) / before;
  const QPoint onScreen = mapToParent(anchor);
  setZoom(zoom);
  auto* area =
      parentWidget() ? qobject_cast<QScrollArea*>(parentWidget()->parentWidget()) : nullptr;
  if (!area || area->widget() != this) return;
  // ...then the scroll area sizes this view for the new zoom now (setWidgetResizable
  // updates its scroll bars at once), and scrolls the point back under the anchor.
  area->setWidgetResizable(true);
  const QPointF after = imageRect().topLeft() + point * scale();
  area->horizontalScrollBar()->setValue(int(std::lround(after.x() - onScreen.x())));
  area->verticalScrollBar()->setValue(int(std::lround(after.y() - onScreen.y())));
}

void ImageView::setMarkedPixel(int x, int y) {
  m_marked = {x, y};
  update();
}

QRectF ImageView::imageRect() const {
  if (m_picture.isNull()) return {};
  const double s = scale();
  const QSizeF size(m_picture.width() * s, m_picture.height() * s);
  // Centred when smaller than the widget.
  return {QPointF(std::max(0.0, (width() - size.width()) / 2),
                  std::max(0.0, (height() - size.height()) / 2)),
          size};
}

QPoint ImageView::pixelAt(const QPoint& position) const {
  const QRectF r = imageRect();
  if (r.isEmpty() || !r.contains(position)) return {-1, -1};
  const double s = scale();
  const int x = std::min(m_picture.width() - 1, int((position.x() - r.left()) / s));
  const int y = std::min(m_picture.height() - 1, int((position.y() - r.top()) / s));
  return {x, y};
}

QPointF ImageView::positionOf(int x, int y) const {
  const QRectF r = imageRect();
  return r.topLeft() + QPointF(x * scale(), y * scale());
}

QSize ImageView::sizeHint() const {
  if (m_picture.isNull() || m_zoom == 0) return {320, 240};
  return m_picture.size() * m_zoom;
}

void ImageView::updateSize() {
  // With a whole-number zoom the widget is as large as the image (the scroll area scrolls);
  // fitting, it takes whatever space it gets.
  if (!m_picture.isNull() && m_zoom > 0)
    setMinimumSize(m_picture.size() * m_zoom);
  else
    setMinimumSize(0, 0);
  updateGeometry();
}

void ImageView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  if (m_picture.isNull()) {
    painter.setPen(palette().color(QPalette::BrightText));
    painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, m_hint);
    return;
  }
  const QRectF r = imageRect();
  painter.setRenderHint(QPainter::SmoothPixmapTransform, false);  // nearest neighbour
  painter.drawImage(r, m_picture);
  if (m_marked.x() >= 0 && m_marked.x() < m_picture.width() && m_marked.y() >= 0 &&
      m_marked.y() < m_picture.height()) {
    // The chosen pixel: a frame at least 9 screen pixels wide, dark then bright.
    const double s = scale();
    const QPointF corner = positionOf(m_marked.x(), m_marked.y());
    const double size = std::max(9.0, s);
    const QRectF frame(corner.x() + s / 2 - size / 2, corner.y() + s / 2 - size / 2, size, size);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(Qt::black, 3));
    painter.drawRect(frame.adjusted(-1, -1, 1, 1));
    painter.setPen(QPen(QColor(255, 230, 0), 1.5));
    painter.drawRect(frame);
  }
}

void ImageView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint p = pixelAt(event->pos());
  if (p != m_hovered) {
    m_hovered = p;
    emit pixelHovered(p.x(), p.y());
  }
}

void ImageView::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return;
  const QPoint p = pixelAt(event->pos());
  if (p.x() < 0) return;
  setMarkedPixel(p.x(), p.y());
  emit pixelClicked(p.x(), p.y());
}

void ImageView::leaveEvent(QEvent*) {
  if (m_hovered.x() >= 0) {
    m_hovered = {-1, -1};
    emit pixelHovered(-1, -1);
  }
}

void ImageView::wheelEvent(QWheelEvent* event) {
  if (!(event->modifiers() & Qt::ControlModifier)) {
    event->ignore();  // the scroll area scrolls
    return;
  }
  // The pixel under the cursor stays under it.
  if (event->angleDelta().y() > 0)
    zoomInAt(event->position().toPoint());
  else if (event->angleDelta().y() < 0)
    zoomOutAt(event->position().toPoint());
  event->accept();
}

}  // namespace raylab::app
