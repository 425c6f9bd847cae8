#pragma once
// The depth of a binary tree's deepest leaf, for --stats (the root is at depth 0). Walked
// with a stack, not recursion: a badly split tree can be as deep as it has primitives.
#include <algorithm>
#include <utility>
#include <vector>

namespace rt {

// leaf(ref) says whether ref ends the walk; children(ref) gives an inner node's two.
template <class Ref, class Leaf, class Children>
int tree_depth(Ref root, Leaf&& leaf, Children&& children) {
    int deepest = 0;
    std::vector<std::pair<Ref, int>> stack{{root, 0}};
    while (!stack.empty()) {
        const auto [ref, d] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, d);
        if (leaf(ref)) continue;
        const auto [left, right] = children(ref);
        stack.push_back({left, d + 1});
        stack.push_back({right, d + 1});
    }
    return deepest;
}

}  // namespace rt
