#include "ActionTable.h"

#include <QAction>
#include <QMenu>

namespace raylab::app {

QList<QAction*> ActionTable::add(QMenu* menu, const std::vector<ActionRow>& rows,
                                 QObject* context) {
  QList<QAction*> added;
  for (const ActionRow& row : rows) {
    if (row.text.isEmpty()) {
      menu->addSeparator();
      added.append(nullptr);
      continue;
    }
    QAction* a = menu->addAction(row.text);
    a->setToolTip(row.tip);
    a->setStatusTip(row.tip);
    a->setShortcuts(row.keys);
    a->setCheckable(row.checkable || row.toggled);
    if (row.triggered) QObject::connect(a, &QAction::triggered, context, row.triggered);
    if (row.toggled) QObject::connect(a, &QAction::toggled, context, row.toggled);
    if (row.enabledWhen) {
      m_conditions.emplace_back(a, row.enabledWhen);
      a->setEnabled(row.enabledWhen());
    }
    added.append(a);
  }
  return added;
}

void ActionTable::refresh() const {
  for (const auto& [action, enabled] : m_conditions)
    if (action) action->setEnabled(enabled());
}

}  // namespace raylab::app
