// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

// One function per scene, each in its own file; makeScenes() lists them in the order of the note.
#include "ui/compute/scene.h"

namespace grazelab::ui {

Scene::Spec grazingFamilyScene();   // Lemma 2.1
Scene::Spec onePeriodicScene();     // Theorem 2.1
Scene::Spec perturbationScene();    // Theorem 2.2
Scene::Spec randomStartsScene();    // Theorem 2.3
Scene::Spec stickingScene();        // lambda > 4/3
Scene::Spec detunedScene();         // off 1:2
Scene::Spec nearGrazingScene();     // Poincaré section
Scene::Spec landscapeScene();       // a map of first flights over the grazing-start plane
Scene::Spec accuracyScene();        // methods against the exact solver
Scene::Spec modesScene();           // nonlinear normal modes: periodic impacting families
Scene::Spec threeMassesScene();     // a chain of N masses: 1:2:3 and what carries over
Scene::Spec grazingSetsScene();     // Lemma 2.1 for other resonances: grazing sets of 2 and 3 modes
Scene::Spec chainOnePeriodicScene();  // Theorem 2.1 for N masses: 1IPP orbits near their grazing limit
Scene::Spec eightMassesScene();     // a string of eight masses, the stop inside it: exact touches
Scene::Spec chainModesScene();      // nonlinear modes of three masses: Krein collisions

/// The landscape's map for these parameters: the grazing-start plane over the region of
/// params.mapRegion (u1 in units of d, v1 in units of d w2), 256 x 256 runs of 10 contacts.
core::MapSpec landscapeSpec(const Params& params, const DerivedModel& derived);

}  // namespace grazelab::ui
