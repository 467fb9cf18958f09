#pragma once

#include "MainWindow.h"

#include <memory>

namespace raylab::app {

/**
 * \brief View > Language: a new window built in the language now installed, carrying what
 * the old one showed as state, never by copying widget values one by one.
 *
 * The new window takes the old one's document (file, edits, undo history), its layout, the
 * selected object, the presentation mode and the rendered image's algorithm and spp. An
 * open lesson stays open at its step, staged again by the lesson player (issue 33); without
 * one, the ray-tree panel's view state (RayTreePanel::viewState: algorithm, pixel, sample,
 * bundle, chosen ray, colours, filters, frame, selected ray) is applied and traced again.
 * The old window is left hidden; the caller deletes it.
 */
std::unique_ptr<MainWindow> rebuildWindow(MainWindow& window);

}  // namespace raylab::app
