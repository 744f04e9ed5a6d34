// Questions about a model's body tree that the plugin and the runtime both ask (header-only:
// the plugin library depends on MuJoCo alone, and the runtime includes it without linking more).
#ifndef SSC_PLUGIN_BODY_TREE_H_
#define SSC_PLUGIN_BODY_TREE_H_

#include <mujoco/mujoco.h>

namespace ssc {

// Whether `body` is `root` or one of its descendants (the world body 0 is nobody's descendant
// but its own).
inline bool IsInSubtree(const mjModel* m, int body, int root) {
  while (body > 0 && body != root) body = m->body_parentid[body];
  return body == root;
}

}  // namespace ssc

#endif  // SSC_PLUGIN_BODY_TREE_H_
