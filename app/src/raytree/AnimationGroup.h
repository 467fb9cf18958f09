#pragma once

#include "raylab/vis/BounceAnimation.h"

#include <QGroupBox>

#include <functional>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class QTimer;

namespace raylab::app {

/**
 * \brief The ray-tree panel's "Bounce animation" group: the reveal order and pace, the
 * transport (Back, Play, Pause, Step), the frame slider and the status line.
 *
 * It owns the frame number and the timer; the picture is the panel's. Every change of the
 * frame (a tick, a button, the slider, setFrame) is reported by frameChanged, and the panel
 * shows vis::revealFrame for it: the picture is always a function of the frame number. Play
 * only starts the timer, whose ticks add `speed` frames; Step forward / back jump to the next
 * / previous step boundary (a multiple of framesPerStep). The frame count is asked of the
 * panel (it depends on the tree and on animation()).
 */
class AnimationGroup : public QGroupBox {
  Q_OBJECT

 public:
  /// Interval of the animation timer, ms (25 ticks per second).
  static constexpr int kTickMs = 40;
  /// Frames a ray front takes to travel its segment (vis::AnimationSettings::framesPerStep).
  static constexpr int kFramesPerStep = 12;

  /// `frameCount` answers how many frames the shown tree has (1: no tree).
  explicit AnimationGroup(std::function<int()> frameCount, QWidget* parent = nullptr);

  /// The order and pace chosen (framesPerStep is kFramesPerStep).
  vis::AnimationSettings animation() const;
  /// Sets the order and rays per step (the window's state, a test).
  void setAnimation(const vis::AnimationSettings& settings);
  /// Paces the processing order for a new tree of `rays` rays (no frameChanged).
  void paceFor(int rays);

  int frame() const { return m_frame; }
  /// Shows frame `frame`, clamped to the frames there are.
  void setFrame(int frame);
  /// The slider, the frame label and the buttons after the tree changed.
  void updateControls();
  void play();
  void pause();
  bool playing() const;
  /// One timer tick: `speed` frames on (fractions add up over ticks); pauses at the end.
  void tick();
  /// To the end of the step being played (or of the next one at a boundary).
  void stepForward();
  /// Back to the end of the previous step.
  void stepBack();
  /// Frames per tick (1/8 to 16).
  double speed() const;
  /// Chooses the speed nearest to `framesPerTick`.
  void setSpeed(double framesPerTick);
  /// The step being played at `frame` (0-based), -1 at frame 0.
  static int stepAt(int frame);
  /// The status line under the transport.
  void setStatus(const QString& text);

 signals:
  /// The frame shown changed (or was shown again): the panel draws it.
  void frameChanged(int frame);

 private:
  QWidget* buildTransport();
  QWidget* buildFrameRow();
  void reorder();

  std::function<int()> m_frameCount;
  int m_frame = 0;
  double m_phase = 0.0;  ///< Fraction of a frame the animation has moved on.
  QComboBox* m_order = nullptr;
  QSpinBox* m_raysPerStep = nullptr;
  QSlider* m_speed = nullptr;
  QLabel* m_speedLabel = nullptr;
  QPushButton* m_play = nullptr;
  QPushButton* m_pause = nullptr;
  QPushButton* m_stepForward = nullptr;
  QPushButton* m_stepBack = nullptr;
  QSlider* m_frameSlider = nullptr;
  QLabel* m_frameLabel = nullptr;
  QLabel* m_statusLabel = nullptr;
  QTimer* m_timer = nullptr;
};

}  // namespace raylab::app
