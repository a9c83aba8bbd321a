#pragma once
/// @file
/// cyber-planner's one way in: everything a program needs to plan the motions of a robot
/// described as data (docs/design.md, "Components"; the method is docs/algorithm.md).
///
///   auto planner = cyber::planner::MotionPlanner::create(model);  // the grids, once per robot
///   cyber::planner::PlanRequest request;                         // start, goal, held pieces, scene
///   auto plan = planner.value().plan(request);                   // Result<Plan>: a trajectory or why not
///
/// The types: RobotModel (robot_model.hpp: joints, links, pieces, scenes, drives) with its
/// PlannerSettings (planner_settings.hpp: every tuned number, each with its reason); MotionPlanner,
/// PlanRequest and Plan (motion_planner.hpp); the Trajectory a plan carries and the checks that
/// read one (trajectory.hpp); PlanStatus and Result (types.hpp). chain.hpp (the joint chain, its
/// motors and dynamics) and collision_world.hpp (distances to a scene) serve the tools that draw
/// or simulate a robot. Everything else is the planner's own (planner/src).

#include "cyber/planner/chain.hpp"
#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "cyber/planner/planner_settings.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/trajectory.hpp"
#include "cyber/planner/types.hpp"
