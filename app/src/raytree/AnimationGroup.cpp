// The ray-tree panel's bounce-animation controls: order, pace, transport and frame.
#include "raytree/AnimationGroup.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>

#include <algorithm>
#include <climits>
#include <cmath>
#include <iterator>
#include <utility>

namespace raylab::app {

namespace {

/// Frames the animation moves on per timer tick, by speed-slider position: slower than
/// one frame a tick for following a single bounce, faster for a bushy tree.
constexpr double kSpeeds[] = {0.125, 0.25, 0.5, 1.0, 2.0, 3.0, 4.0, 8.0, 16.0};
/// Processing order: at most this many steps per animation when rays per step is chosen
/// automatically (a bushy distributed tree still plays in about half a minute).
constexpr int kAutoMaxSteps = 120;

}  // namespace

AnimationGroup::AnimationGroup(std::function<int()> frameCount, QWidget* parent)
    : QGroupBox(tr("Bounce animation"), parent), m_frameCount(std::move(frameCount)) {
  auto* form = new QFormLayout(this);

  // Order and pace.
  m_order = new QComboBox;
  m_order->setObjectName(QStringLiteral("order"));
  m_order->addItem(tr("Depth by depth"), int(vis::RevealOrder::Depth));
  m_order->addItem(tr("Processing order"), int(vis::RevealOrder::Processing));
  m_order->setToolTip(
      tr("Depth by depth: every ray of one depth travels at once.\n"
         "Processing order: ray after ray, as the engine's queue takes them."));
  form->addRow(tr("Order"), m_order);
  m_raysPerStep = new QSpinBox;
  m_raysPerStep->setObjectName(QStringLiteral("raysPerStep"));
  m_raysPerStep->setRange(1, 100000);
  m_raysPerStep->setToolTip(tr("Processing order: rays that start together in one step"));
  form->addRow(tr("Rays per step"), m_raysPerStep);
  connect(m_order, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] { reorder(); });
  connect(m_raysPerStep, qOverload<int>(&QSpinBox::valueChanged), this, [this] { reorder(); });
  m_raysPerStep->setEnabled(false);

  m_speed = new QSlider(Qt::Horizontal);
  m_speed->setRange(0, int(std::size(kSpeeds)) - 1);
  m_speed->setValue(4);  // 2x
  m_speed->setToolTip(tr("How fast the rays travel: frames the animation moves on per tick "
                         "(%1 ticks a second), from 1/8 to 16")
                          .arg(1000 / kTickMs));
  m_speedLabel = new QLabel;
  m_speedLabel->setMinimumWidth(QFontMetrics(font()).horizontalAdvance(QStringLiteral("0.125x  ")));
  const auto speedText = [this] { m_speedLabel->setText(QStringLiteral("%1x").arg(speed())); };
  speedText();
  connect(m_speed, &QSlider::valueChanged, this, speedText);
  auto* speed = new QHBoxLayout;
  speed->addWidget(m_speed, 1);
  speed->addWidget(m_speedLabel);
  form->addRow(tr("Speed"), speed);

  form->addRow(buildTransport());
  form->addRow(tr("Frame"), buildFrameRow());

  m_statusLabel = new QLabel;
  m_statusLabel->setWordWrap(true);
  m_statusLabel->setFrameShape(QFrame::StyledPanel);
  m_statusLabel->setMargin(6);
  m_statusLabel->setMinimumHeight(2 * QFontMetrics(font()).lineSpacing() + 12);
  m_statusLabel->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  form->addRow(m_statusLabel);

  m_timer = new QTimer(this);
  m_timer->setInterval(kTickMs);
  connect(m_timer, &QTimer::timeout, this, [this] { tick(); });
}

QWidget* AnimationGroup::buildTransport() {
  m_play = new QPushButton(style()->standardIcon(QStyle::SP_MediaPlay), tr("Play"));
  m_pause = new QPushButton(style()->standardIcon(QStyle::SP_MediaPause), tr("Pause"));
  m_stepBack = new QPushButton(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("Back"));
  m_stepForward = new QPushButton(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("Step"));
  m_play->setObjectName(QStringLiteral("play"));
  m_pause->setObjectName(QStringLiteral("pause"));
  m_stepBack->setObjectName(QStringLiteral("stepBack"));
  m_stepForward->setObjectName(QStringLiteral("stepForward"));
  m_play->setToolTip(tr("Play the bounces from where the animation stands"));
  m_pause->setToolTip(tr("Stop at the current frame"));
  m_stepBack->setToolTip(tr("Back to the end of the previous step"));
  m_stepForward->setToolTip(tr("On to the end of the next step"));
  connect(m_play, &QPushButton::clicked, this, [this] { play(); });
  connect(m_pause, &QPushButton::clicked, this, [this] { pause(); });
  connect(m_stepBack, &QPushButton::clicked, this, [this] { stepBack(); });
  connect(m_stepForward, &QPushButton::clicked, this, [this] { stepForward(); });
  auto* row = new QWidget;
  auto* buttons = new QHBoxLayout(row);
  buttons->setContentsMargins(0, 0, 0, 0);
  buttons->setSpacing(4);
  for (QPushButton* button : {m_stepBack, m_play, m_pause, m_stepForward})
    buttons->addWidget(button);
  return row;
}

QWidget* AnimationGroup::buildFrameRow() {
  m_frameSlider = new QSlider(Qt::Horizontal);
  m_frameSlider->setObjectName(QStringLiteral("frameSlider"));
  m_frameSlider->setToolTip(tr("Drag to any frame of the animation"));
  connect(m_frameSlider, &QSlider::valueChanged, this, [this](int value) {
    if (value != m_frame) {
      pause();
      setFrame(value);
    }
  });
  m_frameLabel = new QLabel;
  m_frameLabel->setMinimumWidth(
      QFontMetrics(font()).horizontalAdvance(QStringLiteral("0000 of 0000")));
  m_frameLabel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  auto* row = new QWidget;
  auto* frame = new QHBoxLayout(row);
  frame->setContentsMargins(0, 0, 0, 0);
  frame->addWidget(m_frameSlider, 1);
  frame->addWidget(m_frameLabel);
  return row;
}

vis::AnimationSettings AnimationGroup::animation() const {
  vis::AnimationSettings a;
  a.order = vis::RevealOrder(m_order->currentData().toInt());
  a.framesPerStep = kFramesPerStep;
  a.raysPerStep = m_raysPerStep->value();
  return a;
}

void AnimationGroup::setAnimation(const vis::AnimationSettings& settings) {
  m_order->setCurrentIndex(m_order->findData(int(settings.order)));
  m_raysPerStep->setValue(settings.raysPerStep);
}

void AnimationGroup::paceFor(int rays) {
  const QSignalBlocker block(m_raysPerStep);
  m_raysPerStep->setValue(std::max(1, (rays + kAutoMaxSteps - 1) / kAutoMaxSteps));
}

void AnimationGroup::reorder() {
  // A tree shown whole stays whole in the new order.
  const int count = m_frameCount();
  const bool wasDone = count > 1 && m_frame >= count - 1;
  m_raysPerStep->setEnabled(animation().order == vis::RevealOrder::Processing);
  setFrame(wasDone ? INT_MAX : m_frame);
}

void AnimationGroup::setFrame(int frame) {
  m_frame = std::clamp(frame, 0, m_frameCount() - 1);
  updateControls();
  emit frameChanged(m_frame);
}

void AnimationGroup::updateControls() {
  const int count = m_frameCount();
  const bool has = count > 1;
  const int last = has ? count - 1 : 0;
  {
    const QSignalBlocker block(m_frameSlider);
    m_frameSlider->setRange(0, last);
    m_frameSlider->setPageStep(kFramesPerStep);
    m_frameSlider->setValue(m_frame);
  }
  m_frameLabel->setText(has ? tr("%1 of %2").arg(m_frame).arg(last) : tr("no tree yet"));
  for (QWidget* w : {static_cast<QWidget*>(m_frameSlider), static_cast<QWidget*>(m_stepBack),
                     static_cast<QWidget*>(m_stepForward)})
    w->setEnabled(has);
  const bool running = playing();
  m_play->setEnabled(has && !running);
  m_pause->setEnabled(has && running);
}

void AnimationGroup::play() {
  if (m_frameCount() <= 1) return;
  // From the end, play again from the start.
  if (m_frame >= m_frameCount() - 1) setFrame(0);
  m_timer->start();
  updateControls();
}

void AnimationGroup::pause() {
  if (!m_timer->isActive()) return;
  m_timer->stop();
  updateControls();
}

bool AnimationGroup::playing() const { return m_timer->isActive(); }

void AnimationGroup::tick() {
  // Fractions of a frame add up over ticks: at 1/4 a frame moves every fourth tick.
  m_phase += speed();
  const int frames = int(std::floor(m_phase));
  m_phase -= frames;
  const int last = m_frameCount() - 1;
  if (m_frame + frames >= last) m_timer->stop();
  setFrame(std::min(m_frame + frames, last));
}

void AnimationGroup::stepForward() {
  pause();
  setFrame((m_frame / kFramesPerStep + 1) * kFramesPerStep);
}

void AnimationGroup::stepBack() {
  pause();
  setFrame(m_frame <= 0 ? 0 : (m_frame - 1) / kFramesPerStep * kFramesPerStep);
}

double AnimationGroup::speed() const {
  return kSpeeds[std::clamp(m_speed->value(), 0, int(std::size(kSpeeds)) - 1)];
}

void AnimationGroup::setSpeed(double framesPerTick) {
  int best = 0;
  for (int i = 0; i < int(std::size(kSpeeds)); ++i)
    if (std::abs(kSpeeds[i] - framesPerTick) < std::abs(kSpeeds[best] - framesPerTick)) best = i;
  m_speed->setValue(best);
}

int AnimationGroup::stepAt(int frame) {
  // Frame 0 shows nothing; step s travels during frames s F + 1 .. (s + 1) F.
  if (frame <= 0) return -1;
  return (frame - 1) / kFramesPerStep;
}

void AnimationGroup::setStatus(const QString& text) { m_statusLabel->setText(text); }

}  // namespace raylab::app
