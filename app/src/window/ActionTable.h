#pragma once

#include <QKeySequence>
#include <QList>
#include <QPointer>
#include <QString>

#include <functional>
#include <utility>
#include <vector>

class QAction;
class QMenu;
class QObject;

namespace raylab::app {

/// One action of the window's menus: what it says, its keys, what it does and when it can.
struct ActionRow {
  QString text;                   ///< The menu text (with its & accelerator); empty: a separator.
  QString tip;                    ///< Tooltip and status tip; also the shortcut table's words.
  QList<QKeySequence> keys = {};  ///< Its shortcuts, the first shown in the menu.
  std::function<void()> triggered = {};    ///< What choosing it does.
  std::function<bool()> enabledWhen = {};  ///< Enabled only while this is true (none: always).
  std::function<void(bool)> toggled = {};  ///< For an on/off action: called when it changes.
  bool checkable = false;                  ///< An on/off action (also when `toggled` is set).
};

/**
 * \brief The window's menus built from tables of ActionRow, one row per action (ParaView's
 * menu builders and reactions, pqParaViewMenuBuilders): the menus, the shortcuts, the
 * tooltips and Help > Keyboard shortcuts (MainWindow::shortcutTable reads the menus) all come
 * from the one row.
 *
 * A row's `enabledWhen` is asked again by refresh(), which the window calls whenever what it
 * depends on may have changed (the selection, a menu about to show), so a disabled action's
 * shortcut does nothing while its menu item is greyed.
 */
class ActionTable {
 public:
  /// Adds one action per row to `menu`, in order (an empty text adds a separator, returned
  /// as null); `context` owns the connections. Returns the actions in the rows' order.
  QList<QAction*> add(QMenu* menu, const std::vector<ActionRow>& rows, QObject* context);
  /// Enables each action whose row has an `enabledWhen` by its answer now.
  void refresh() const;

 private:
  std::vector<std::pair<QPointer<QAction>, std::function<bool()>>> m_conditions;
};

}  // namespace raylab::app
