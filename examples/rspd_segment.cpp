/*
 * rspd_segment: detect every plane of a point cloud file with pcl::RobustPlaneSegmentation and
 * write the labelled cloud, a CSV of the planes and a picture.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_io.h"
#include "command_line.h"
#include "render_png.h"

#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <pcl/console/print.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <new>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using rspd_tools::OptionArgument;
using rspd_tools::parseInteger;
using rspd_tools::UsageError;

const char* const kUsage =
    "usage: rspd_segment [INPUT.pcd|INPUT.ply | --demo] [-o OUT.pcd] [--planes OUT.csv] [--png OUT.png]"
    " [--png-size WxH] [-k 50] [--normal-scale fixed|adaptive|auto] [--given-normals check|keep] [--depth-levels keep|dither] [--coplanar-merge on|off] [--left-normals auto|trimmed|pca] [--shifted-grid on|off] [--rim-retest on|once|off] [--left-retest on|off] [--position-planes on|off] [--position-surfaces on|off] [--position-normals on|off] [--position-bend-band on|off] [--position-bend-slabs on|off] [--position-join on|off] [--position-ladder on|off] [--ladder-rungs on|off] [--tail-odds on|off] [--surrounding-clutter on|off] [--member-gaps on|off] [--rim-bands on|off] [--release on|off] [--released-planes on|off] [--edge-sides on|off] [--edge-corners on|off] [--edge-wedges on|off] [--step-sides on|off] [--step-regions on|off] [--thick-join on|off] [--small-thick-join on|off] [--noisy-groups on|off] [--noisy-lone on|off] [--noisy-ladder on|off] [--noisy-t2 on|off] [--thick-follow on|off] [--support on|off] [--support-clutter on|off] [--final-parts on|off] [--final-refit on|off] [--connected-parts on|off] [--bent-split on|off] [--bent-side-mnd on|off] [--bent-normals on|off] [--layer-merge on|off] [--layer-steps on|off] [--step-split on|off] [--across-steps on|off]"
    " [--normal-fit pca|trimmed] [--edge-normals on|off] [--frame planes|axes] [--outlier-seeds retest|drop|keep] [--volume-layers on|off] [--final-volume-layers on|off] [--in-band-layers on|off] [--flat-layers on|off] [--small-completion on|off] [--bounded-reestimate on|off] [--noisy-bent-split on|off] [--curved-check on|off] [--late-curved on|off] [--curved-turn on|off] [--curved-fold-sides on|off] [--tube-check on|off] [--curved-parts on|off] [--bend-test noise|share] [--hinge-normals on|off] [--assign edges|tails|all|none] [--threads N] [-v]";

const char* const kHelp =
    "Detect every plane of a point cloud (RSPD, Araujo & Oliveira 2020).\n"
    "\n"
    "  INPUT            .pcd (ascii, binary, binary_compressed) or .ply; normal_x/y/z are used if present\n"
    "  --demo           run on the built-in synthetic room (also the default without INPUT);\n"
    "                   writes nothing unless an output is asked for\n"
    "  -o OUT.pcd       binary PCD: every input point and field, plus uint32 'label' (0 = no plane,\n"
    "                   1..K by decreasing size) and a colour 'rgb' per plane\n"
    "  --planes OUT.csv one row per plane: label,a,b,c,d,points,cx,cy,cz,extent_u,extent_v,mdp,mnd\n"
    "  --png OUT.png    two views of the labelled cloud, from above and from below\n"
    "                   (--png-size WxH, default 1600x800)\n"
    "  -k N             neighbours per point for normals and the growth graph: 3..1000, or 0 for\n"
    "                   automatic (the default): eps/2 between 15 and 50, i.e. the paper's 50 from\n"
    "                   100,000 points on\n"
    "  --normal-scale S estimated normals from the k-neighbourhood ('fixed', the paper's), from the\n"
    "                   finest scale that resolves a surface where noise swamps the k-neighbourhood\n"
    "                   ('adaptive'), or that only when it swamps most of them ('auto', the\n"
    "                   default); with the input's normals, 'auto' also estimates them again\n"
    "                   when they are noise at the k-scale (see --given-normals)\n"
    "  --given-normals check|keep  the input's normals are estimated again when most\n"
    "                   k-neighbourhoods resolve no surface and the normals agree with their\n"
    "                   neighbours' no better than those neighbourhoods' PCA normals, or (under\n"
    "                   100,000 points) when most finer neighbourhoods resolve a face they tilt off,\n"
    "                   or they tilt off it where most 50-neighbourhoods' PCA normals do ('check',\n"
    "                   the default, with --normal-scale auto); 'keep' uses them as given\n"
    "  --depth-levels keep|dither  where the depths along the camera's axis (the file's\n"
    "                   VIEWPOINT) take a structured-light or stereo camera's levels, 'dither'\n"
    "                   draws each sample's depth again within its level's bin, for the detection\n"
    "                   only, so the levels' flat terraces are no planes ('keep', the default:\n"
    "                   the samples as given)\n"
    "  --coplanar-merge on|off  a group joins another only if most of its points lie within MDP\n"
    "                   of the plane the merged group keeps (default on; off = the paper)\n"
    "  --left-normals auto|trimmed|pca  the small-plane pass splits the points it left a\n"
    "                   second time, on other normals: 'auto' (the default) on those of their\n"
    "                   neighbourhoods' trimmed planes with the input's normals, and on PCA\n"
    "                   normals narrowed to one face at edges with normals estimated here;\n"
    "                   'trimmed' on trimmed planes' normals with both; 'pca' never (the paper)\n"
    "  --shifted-grid on|off  the small-plane pass also splits what it left on a second octree\n"
    "                   whose cells are moved by a third of a cell, keeping seeds no noisier than\n"
    "                   the planes found (default on; off = the paper's one octree)\n"
    "  --rim-retest on|once|off  in the small-plane pass, a cell failing only T3 is tested\n"
    "                   again on its inliers, and theirs while T3 still fails, and may seed a\n"
    "                   plane (default on; once = one retest; off = it seeds nothing)\n"
    "  --left-retest on|off  on the narrowed or trimmed normals of what growth left (see\n"
    "                   --left-normals), a rim cell's inliers are tested again down to 16 of them,\n"
    "                   the faces narrowed normals resolve, instead of k + 1 (default on;\n"
    "                   off = as many as the cells)\n"
    "  --position-planes on|off  after the last assignment, what no plane holds is searched for\n"
    "                   planes by position alone (as noisy as the noisiest plane found at most, no\n"
    "                   bend beyond noise, no layer of a plane found) (default on; off = the paper)\n"
    "  --position-surfaces on|off  where that search ended at a plane turned down, what is left\n"
    "                   on a surface is searched again (default on; off = not)\n"
    "  --position-normals on|off  there, a member's neighbourhood plane must be nearer parallel to\n"
    "                   its plane than perpendicular (default on; off = by position alone)\n"
    "  --position-bend-band on|off  a plane found by position that bends beyond noise is judged\n"
    "                   again with the free points beside it left out as in a neighbouring\n"
    "                   plane's band (default on; off = its members alone)\n"
    "  --position-bend-slabs on|off  and if it still bends, again without its points in the\n"
    "                   bands of the planes found beside it (default on; off = not)\n"
    "  --position-join on|off  a plane found by position that lies on a plane beside it gives\n"
    "                   it its points within its band (default on; off = they stay in none)\n"
    "  --position-ladder on|off  there, planes up to twice as noisy as the noisiest kept, step by\n"
    "                   step while a step keeps a noisier one (default on; off = one step)\n"
    "  --ladder-rungs on|off  and on, a step at a time, where a step kept no plane but turned one\n"
    "                   down for its noise alone within the next step (default on; off = not)\n"
    "  --tail-odds on|off  the last assignment takes a plane's noise tail (3-4 robust sigma) only as\n"
    "                   far as its noise is likelier than the clutter measured beside it (default\n"
    "                   on; off = every plane's 4 sigma tail)\n"
    "  --surrounding-clutter on|off  the tail odds also count the clutter around a plane over\n"
    "                   its footprint (both sides), the tail may end below 3 robust sigma, and\n"
    "                   members beyond it leave (default on; off = the neighbourhood count alone)\n"
    "  --member-gaps on|off  the last assignment gives a point to a plane only where it lies among\n"
    "                   the plane's members (its gap to the nearest within 6 times theirs), not\n"
    "                   through the clutter beside a rim (default on; off = by distance, normal\n"
    "                   and neighbours alone)\n"
    "  --rim-bands on|off  beside a plane with no clutter around it, the last assignment also gives\n"
    "                   it a point within its band whose neighbours in the band are at least a\n"
    "                   third its members, neighbours off the band (one at least) not counted:\n"
    "                   a rim whose normals a surface beside it tilts (default on; off = most\n"
    "                   neighbours)\n"
    "  --release on|off once growth is stable, members farther than 3 robust sigma from their\n"
    "                   plane are offered to the neighbouring planes (default on; off = the paper:\n"
    "                   members are never revoked)\n"
    "  --released-planes on|off  with --release on, released points no plane takes that form a\n"
    "                   plane by the paper's tests become one (default on; off = they go back)\n"
    "  --edge-sides on|off  where two planes meet, a point whose projection onto its plane lies\n"
    "                   beyond the line where they meet leaves it for the other plane or none\n"
    "                   (default on; off = the paper)\n"
    "  --edge-corners on|off  with --edge-sides on, a point inside the corner two planes make\n"
    "                   goes to the nearer of them, relative to its noise (default on; off = as\n"
    "                   before: the plane that reached it first keeps it)\n"
    "  --edge-wedges on|off  with --edge-sides on, a point outside the edge of two planes\n"
    "                   (beyond each) goes to the one it lies farther from, relative to their\n"
    "                   noise, within both bands (default on; off = as before: to none)\n"
    "  --thick-join on|off  the split also joins touching cells that fail only the paper's\n"
    "                   distance test (T1) and agree on their plane; once growth is stable, what\n"
    "                   it left of a group seeds a plane if it passes the tests (default on;\n"
    "                   off = the paper)\n"
    "  --small-thick-join on|off  the small-plane pass joins its thick cells the same way\n"
    "                   (default on; needs --thick-join on)\n"
    "  --noisy-groups on|off  small-plane seeds too noisy alone are joined where they touch\n"
    "                   and agree; a group of eps samples that passes the tests, is flat and is\n"
    "                   at most twice as noisy as the planes found seeds a plane (default on)\n"
    "  --noisy-lone on|off  such a seed that joins no other, or a group of fewer than eps\n"
    "                   samples, seeds a plane on the same terms but eps, which its grown plane\n"
    "                   must reach (default on; needs --noisy-groups on)\n"
    "  --noisy-ladder on|off  once such seeds seeded planes of eps points noisier than every plane\n"
    "                   found, the noisy seeds left are offered again against those, while a step\n"
    "                   seeds such a noisier plane (default on; off = one step)\n"
    "  --noisy-t2 on|off  a plane a noisy seed seeded whose points, once grown, fail the\n"
    "                   paper's normal test (T2) is dropped (default off: kept on its seed's\n"
    "                   estimate; faces whose normals are noise fail it too)\n"
    "  --thick-follow on|off  where noisy seeds seeded planes noisier than the small-plane pass's\n"
    "                   thick cells may be, its thick cells are collected again up to them\n"
    "                   (default on; needs --small-thick-join on)\n"
    "  --step-sides on|off  where two parallel planes make a step deeper than their noise bands,\n"
    "                   a point within the other plane's band goes to it when it holds more of\n"
    "                   the point's neighbours (default on; off = the paper)\n"
    "  --step-regions on|off  before that, a region of a plane that lies off it toward a parallel\n"
    "                   plane beside it goes to that plane when its points lie nearer to it, as\n"
    "                   a window in a wall's noise band (default on; off = points one at a time)\n"
    "  --support on|off last, a point on or beyond its plane's rim, more than 6 times its\n"
    "                   neighbours' spacing from the rest of the plane or more than 2 ahead of\n"
    "                   all of it, and in no other plane's noise band, leaves it; repeated\n"
    "                   while that exposes more (default on; off = the paper)\n"
    "  --support-clutter on|off  with --support on, a point whose plane is no denser within\n"
    "                   its noise band than the clutter outside it, around the point, leaves it\n"
    "                   too, wherever it lies (default on; off = rims alone)\n"
    "  --final-parts on|off  after that, a plane whose points form separate pieces of surface\n"
    "                   is split into them, and a plane of one piece keeps only the points its\n"
    "                   points join to it through neighbour links (default on; off = as left)\n"
    "  --final-refit on|off  once the planes' points are settled, each plane becomes the\n"
    "                   least-squares plane of its points within 2.5 robust sigma before the\n"
    "                   last passes, and again for the planes written (default on; off = the\n"
    "                   paper's robust estimate)\n"
    "  --connected-parts on|off  a plane whose points that pass its inlier test form separate\n"
    "                   parts (no neighbour link between them) is split into them (default on;\n"
    "                   off = the paper)\n"
    "  --bent-split on|off  a plane whose points lie on two planes meeting at an edge (more than\n"
    "                   15 degrees apart, well beyond its noise) is split there (default on;\n"
    "                   off = the paper)\n"
    "  --layer-merge on|off  a plane lying among a larger plane's points, within its noise band\n"
    "                   across its extent, is merged into it: two layers of one noisy face (default\n"
    "                   on; off = they stay apart)\n"
    "  --layer-steps on|off  with the layer merge, a plane whose points' neighbourhoods average\n"
    "                   off its joint plane with the larger one (a window recessed within its\n"
    "                   wall's noise band) is a step, not a layer (default on; off = merged)\n"
    "  --step-split on|off  a region of a plane lying parallel to the rest, offset by a step\n"
    "                   within its noise band (a door 2 cm proud of a wall), is split off as a\n"
    "                   plane (default on; off = it stays in its plane)\n"
    "  --across-steps on|off  a plane whose points lie on two planes beside it, parallel to\n"
    "                   each other and not to it, at least as closely as on its own (a strip\n"
    "                   across a door's edge, half door and half wall) is dropped (default on;\n"
    "                   off = it stays)\n"
    "  --bent-side-mnd on|off  a side of a bent plane passes T2 if its MND is below that of\n"
    "                   the plane it was cut from, where that is past T2's 60 degrees (default on;\n"
    "                   off = T2 at 60 degrees)\n"
    "  --bent-normals on|off  a plane whose sides meet at more than 15 degrees is split there\n"
    "                   also where its noise hides the bend from the positions, if the normals\n"
    "                   turn at the edge in one step (not steadily, as on a curved surface)\n"
    "                   (default on; off = the positions alone)\n"
    "  --normal-fit pca|trimmed   estimated normals by PCA over the k-neighbourhood (default, the\n"
    "                             paper) or from its reweighted least-trimmed-squares plane (more\n"
    "                             accurate at edges, ~20x the normal stage's time)\n"
    "  --edge-normals on|off      estimated normals narrowed to one face near an edge, where that\n"
    "                             turns them by more than noise, and small-plane cells down to 16\n"
    "                             points there (default off; finds small faces at the scale of a\n"
    "                             neighbourhood, but more facets of noisy curved surfaces)\n"
    "  --frame planes|axes        work along the dominant plane orientations (independent of how the\n"
    "                             cloud is rotated) or along its coordinate axes (the paper)\n"
    "  --outlier-seeds retest|drop|keep  drop split seeds whose MND is an outlier among all\n"
    "                   seeds; 'retest' (default) tests each again once growth is stable, on its\n"
    "                   points no plane took (a flat one seeds a plane); keep = the paper\n"
    "  --small-completion on|off  a plane the small-plane pass seeded that growth left\n"
    "                   short of eps, at half of it or more, takes the points of its surface\n"
    "                   within its noise band that no plane or a noisier plane turned from it\n"
    "                   holds, and is kept if that brings it to eps (default on; off = dropped)\n"
    "  --volume-layers on|off  drop a plane a noisy seed seeded when the points beside its\n"
    "                   noise band are four times as dense as within it: where a volume of\n"
    "                   clutter ends, not a surface (default on; off = kept)\n"
    "  --final-volume-layers on|off  the same for every plane once the planes are final, however\n"
    "                   seeded: a thin slab of outliers wrapping a plane (default on; off = only\n"
    "                   noisy seeds' planes are judged)\n"
    "  --in-band-layers on|off  with them, also drop a final plane within whose noise band\n"
    "                   another plane is four times as dense: clutter beside a denser plane,\n"
    "                   not a surface; the layer merge does not join it (default on; off = kept)\n"
    "  --flat-layers on|off  with them, also drop a final plane when the layer beside its band\n"
    "                   holds more points than it and the next layer as many again: a layer of\n"
    "                   a volume of clutter (default on; off = the ratio rule alone)\n"
    "  --bounded-reestimate on|off  a plane keeps its last estimate when a re-estimate's\n"
    "                   normal spread fails the paper's 60 degree test (default on; off = the\n"
    "                   paper: every re-estimate taken)\n"
    "  --noisy-bent-split on|off  a noisy seed's plane that is not flat once grown, but that two flat\n"
    "                   planes meeting at an edge explain, is split into them (default off:\n"
    "                   it is dropped)\n"
    "  --curved-check on|off  drop planes that are facets of a curved surface: a quadric explains\n"
    "                   a quarter of their residual and bends by half their MND, and their normals\n"
    "                   turn smoothly, not in steps as over a fold (default on; off = the paper)\n"
    "  --late-curved on|off  run that check again once the last assignment has given the planes\n"
    "                   their noise tails, which show the bend a facet's band cut off (default\n"
    "                   on; off = before the last assignment alone)\n"
    "  --curved-turn on|off  the check also calls a plane curved when its quadric bends beyond\n"
    "                   chance and its normals turn across it by half their MND, where noise\n"
    "                   hides the bend from the bounds above (default on; off = those alone)\n"
    "  --curved-fold-sides on|off  normals turning in steps spare a plane the check calls curved\n"
    "                   only if it has 2 eps points, enough for the bent-plane split to cut it\n"
    "                   into two faces (default on; off = at every size)\n"
    "  --tube-check on|off  the check drops a plane as thick as half its narrow side, a thin\n"
    "                   pipe's points from every side folded onto one plane (default on; off =\n"
    "                   judged as other planes)\n"
    "  --curved-parts on|off  the check judges the parts the bent-plane split cut as it judges\n"
    "                   planes (default on; off = kept unjudged)\n"
    "  --hinge-normals on|off  a seed or group of cells is bent at an edge (and seeds nothing)\n"
    "                   only if its two sides' normals turn by more than 15 degrees as their\n"
    "                   planes do (default on; off = positions alone)\n"
    "  --bend-test noise|share  a noisy seed or plane is flat unless a quadric explains more of\n"
    "                   its residual than it explains of a flat plane's noise with as many points,\n"
    "                   and a grown one is thinner than half its narrow side ('noise', the default)\n"
    "                   or unless it explains a quarter ('share', as before)\n"
    "  --assign M       once growth is stable, give points growth left out to a neighbouring plane\n"
    "                   by distance alone: next to two or more planes ('edges'); those and, inside\n"
    "                   one plane, points within its band, or with its normal within 4 robust sigma\n"
    "                   of it ('tails', the default); next to any ('all'); or none ('none', the\n"
    "                   paper); at edges never more than 3 neighbourhood radii from the points\n"
    "                   growth took\n"
    "  --threads N      OpenMP threads (default: OpenMP's default, OMP_NUM_THREADS is honoured)\n"
    "  -v               progress and per-stage timings on stderr\n"
    "\n"
    "Exit status: 0 success, 1 bad input or output, 2 usage error.\n";

/** \brief Command line. */
/** Which normals the small-plane pass's second split refits (--left-normals). */
enum class LeftNormals
{
  Auto,    ///< trimmed for the input's normals, narrowed at edges for those estimated here
  Trimmed, ///< trimmed for the input's and those estimated here
  Pca      ///< none
};

struct Options
{
  std::string input;
  bool demo = false;
  std::string output;
  std::string planes_csv;
  std::string png;
  int png_width = 1600;
  int png_height = 800;
  int k = 0; // automatic
  int threads = 0;  // 0: leave OpenMP's default
  pcl::rspd::NormalScale normal_scale = pcl::rspd::NormalScale::Automatic;
  bool given_normal_check = true;
  bool depth_level_dither = false;
  bool coplanar_merge = true;
  bool rim_retest = true;
  bool rim_retest_until_stable = true;
  bool left_retest = true;
  bool position_planes = true;
  bool position_surfaces = true;
  bool position_normals = true;
  bool position_bend_band = true;
  bool position_bend_slabs = true;
  bool position_join = true;
  bool position_ladder = true;
  bool ladder_rungs = true;
  bool tail_odds = true;
  bool member_gaps = true;
  bool rim_bands = true;
  bool surrounding_clutter = true;
  bool hinge_normals = true;
  bool release = true;
  bool released_planes = true;
  bool edge_sides = true;
  bool edge_corners = true;
  bool edge_wedges = true;
  bool step_sides = true;
  bool step_regions = true;
  bool thick_join = true;
  bool small_thick_join = true;
  bool noisy_groups = true;
  bool noisy_lone = true;
  bool noisy_ladder = true;
  bool noisy_t2 = false;
  bool thick_follow = true;
  bool support = true;
  bool support_clutter = true;
  bool final_parts = true;
  bool final_refit = true;
  LeftNormals left_normals = LeftNormals::Auto;
  bool connected_parts = true;
  bool bent_split = true;
  bool layer_merge = true;
  bool layer_steps = true;
  bool step_split = true;
  bool across_steps = true;
  bool bent_side_mnd = true;
  bool bent_normals = true;
  bool curved_check = true;
  bool late_curved = true;
  bool curved_turn = true;
  bool curved_fold_sides = true;
  bool tube_check = true;
  bool curved_parts = true;
  bool bend_noise_test = true;
  bool drop_outlier_seeds = true;
  bool retest_outlier_seeds = true;
  bool volume_layers = true;
  bool final_volume_layers = true;
  bool in_band_layers = true;
  bool flat_layers = true;
  bool small_completion = true;
  bool bounded_reestimate = true;
  bool noisy_bent_split = false;
  bool dominant_frame = true;
  bool trimmed_normals = false;
  bool edge_normals = false;
  bool shifted_grid = true;
  pcl::rspd::FinalAssignment assignment = pcl::rspd::FinalAssignment::Tails;
  bool verbose = false;
  bool help = false;
};

/** \brief Parse the command line. \throws UsageError */
Options
parseArguments (int argc, char** argv)
{
  Options o;
  bool positional_only = false;
  for (int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    if (positional_only || arg.empty () || arg[0] != '-' || arg == "-")
    {
      if (!o.input.empty ())
        throw UsageError{"more than one input file ('" + o.input + "' and '" + arg + "')"};
      o.input = arg;
      continue;
    }
    if (arg == "--")
    {
      positional_only = true;
      continue;
    }
    OptionArgument option (argc, argv, i);
    arg = option.name ();
    const auto value = [&] { return option.value (); };
    const auto no_value = [&] { option.noValue (); };
    if (arg == "-h" || arg == "--help")
    {
      no_value ();
      o.help = true;
    }
    else if (arg == "--demo")
    {
      no_value ();
      o.demo = true;
    }
    else if (arg == "-v" || arg == "--verbose")
    {
      no_value ();
      o.verbose = true;
    }
    else if (arg == "-o" || arg == "--output")
      o.output = value ();
    else if (arg == "--planes")
      o.planes_csv = value ();
    else if (arg == "--png")
      o.png = value ();
    else if (arg == "--png-size")
    {
      const std::string v = value ();
      const std::size_t x = v.find ('x');
      if (x == std::string::npos || !parseInteger (v.substr (0, x), 16, 16384, o.png_width) ||
          !parseInteger (v.substr (x + 1), 16, 16384, o.png_height))
        throw UsageError{"--png-size needs WIDTHxHEIGHT, each 16..16384 (got '" + v + "')"};
    }
    else if (arg == "-k" || arg == "--neighbours" || arg == "--neighbors")
    {
      const std::string v = value ();
      if (!parseInteger (v, 0, 1000, o.k) || (o.k > 0 && o.k < 3))
        throw UsageError{"-k needs 0 (automatic) or an integer from 3 to 1000 (got '" + v + "')"};
    }
    else if (arg == "--normal-scale")
    {
      const std::string v = value ();
      if (v == "fixed")
        o.normal_scale = pcl::rspd::NormalScale::Fixed;
      else if (v == "adaptive")
        o.normal_scale = pcl::rspd::NormalScale::Adaptive;
      else if (v == "auto")
        o.normal_scale = pcl::rspd::NormalScale::Automatic;
      else
        throw UsageError{"--normal-scale needs 'fixed', 'adaptive' or 'auto' (got '" + v + "')"};
    }
    else if (arg == "--given-normals")
      o.given_normal_check = option.choice ("check", "keep");
    else if (arg == "--depth-levels")
      o.depth_level_dither = option.choice ("dither", "keep");
    else if (arg == "--coplanar-merge")
      o.coplanar_merge = option.choice ("on", "off");
    else if (arg == "--rim-retest")
    {
      const std::string v = value ();
      if (v != "on" && v != "once" && v != "off")
        throw UsageError{"--rim-retest needs 'on', 'once' or 'off' (got '" + v + "')"};
      o.rim_retest = v != "off";
      o.rim_retest_until_stable = v == "on";
    }
    else if (arg == "--left-retest")
      o.left_retest = option.choice ("on", "off");
    else if (arg == "--position-planes")
      o.position_planes = option.choice ("on", "off");
    else if (arg == "--position-surfaces")
      o.position_surfaces = option.choice ("on", "off");
    else if (arg == "--position-normals")
      o.position_normals = option.choice ("on", "off");
    else if (arg == "--position-bend-band")
      o.position_bend_band = option.choice ("on", "off");
    else if (arg == "--position-bend-slabs")
      o.position_bend_slabs = option.choice ("on", "off");
    else if (arg == "--position-join")
      o.position_join = option.choice ("on", "off");
    else if (arg == "--position-ladder")
      o.position_ladder = option.choice ("on", "off");
    else if (arg == "--ladder-rungs")
      o.ladder_rungs = option.choice ("on", "off");
    else if (arg == "--tail-odds")
      o.tail_odds = option.choice ("on", "off");
    else if (arg == "--member-gaps")
      o.member_gaps = option.choice ("on", "off");
    else if (arg == "--rim-bands")
      o.rim_bands = option.choice ("on", "off");
    else if (arg == "--surrounding-clutter")
      o.surrounding_clutter = option.choice ("on", "off");
    else if (arg == "--release")
      o.release = option.choice ("on", "off");
    else if (arg == "--released-planes")
      o.released_planes = option.choice ("on", "off");
    else if (arg == "--edge-sides")
      o.edge_sides = option.choice ("on", "off");
    else if (arg == "--edge-corners")
      o.edge_corners = option.choice ("on", "off");
    else if (arg == "--edge-wedges")
      o.edge_wedges = option.choice ("on", "off");
    else if (arg == "--thick-join")
      o.thick_join = option.choice ("on", "off");
    else if (arg == "--small-thick-join")
      o.small_thick_join = option.choice ("on", "off");
    else if (arg == "--noisy-groups")
      o.noisy_groups = option.choice ("on", "off");
    else if (arg == "--noisy-lone")
      o.noisy_lone = option.choice ("on", "off");
    else if (arg == "--noisy-ladder")
      o.noisy_ladder = option.choice ("on", "off");
    else if (arg == "--noisy-t2")
      o.noisy_t2 = option.choice ("on", "off");
    else if (arg == "--thick-follow")
      o.thick_follow = option.choice ("on", "off");
    else if (arg == "--step-sides")
      o.step_sides = option.choice ("on", "off");
    else if (arg == "--step-regions")
      o.step_regions = option.choice ("on", "off");
    else if (arg == "--left-normals")
    {
      const std::string v = value ();
      if (v == "auto")
        o.left_normals = LeftNormals::Auto;
      else if (v == "trimmed")
        o.left_normals = LeftNormals::Trimmed;
      else if (v == "pca")
        o.left_normals = LeftNormals::Pca;
      else
        throw UsageError{"--left-normals needs 'auto', 'trimmed' or 'pca' (got '" + v + "')"};
    }
    else if (arg == "--support")
      o.support = option.choice ("on", "off");
    else if (arg == "--support-clutter")
      o.support_clutter = option.choice ("on", "off");
    else if (arg == "--final-parts")
      o.final_parts = option.choice ("on", "off");
    else if (arg == "--final-refit")
      o.final_refit = option.choice ("on", "off");
    else if (arg == "--connected-parts")
      o.connected_parts = option.choice ("on", "off");
    else if (arg == "--bent-split")
      o.bent_split = option.choice ("on", "off");
    else if (arg == "--layer-merge")
      o.layer_merge = option.choice ("on", "off");
    else if (arg == "--layer-steps")
      o.layer_steps = option.choice ("on", "off");
    else if (arg == "--step-split")
      o.step_split = option.choice ("on", "off");
    else if (arg == "--across-steps")
      o.across_steps = option.choice ("on", "off");
    else if (arg == "--bent-side-mnd")
      o.bent_side_mnd = option.choice ("on", "off");
    else if (arg == "--bent-normals")
      o.bent_normals = option.choice ("on", "off");
    else if (arg == "--normal-fit")
      o.trimmed_normals = !option.choice ("pca", "trimmed");
    else if (arg == "--edge-normals")
      o.edge_normals = option.choice ("on", "off");
    else if (arg == "--shifted-grid")
      o.shifted_grid = option.choice ("on", "off");
    else if (arg == "--frame")
      o.dominant_frame = option.choice ("planes", "axes");
    else if (arg == "--bounded-reestimate")
      o.bounded_reestimate = option.choice ("on", "off");
    else if (arg == "--noisy-bent-split")
      o.noisy_bent_split = option.choice ("on", "off");
    else if (arg == "--outlier-seeds")
    {
      const std::string v = value ();
      if (v != "retest" && v != "drop" && v != "keep")
        throw UsageError{"--outlier-seeds needs 'retest', 'drop' or 'keep' (got '" + v + "')"};
      o.drop_outlier_seeds = v != "keep";
      o.retest_outlier_seeds = v == "retest";
    }
    else if (arg == "--volume-layers")
      o.volume_layers = option.choice ("on", "off");
    else if (arg == "--final-volume-layers")
      o.final_volume_layers = option.choice ("on", "off");
    else if (arg == "--in-band-layers")
      o.in_band_layers = option.choice ("on", "off");
    else if (arg == "--flat-layers")
      o.flat_layers = option.choice ("on", "off");
    else if (arg == "--small-completion")
      o.small_completion = option.choice ("on", "off");
    else if (arg == "--curved-check")
      o.curved_check = option.choice ("on", "off");
    else if (arg == "--late-curved")
      o.late_curved = option.choice ("on", "off");
    else if (arg == "--curved-turn")
      o.curved_turn = option.choice ("on", "off");
    else if (arg == "--curved-fold-sides")
      o.curved_fold_sides = option.choice ("on", "off");
    else if (arg == "--tube-check")
      o.tube_check = option.choice ("on", "off");
    else if (arg == "--curved-parts")
      o.curved_parts = option.choice ("on", "off");
    else if (arg == "--hinge-normals")
      o.hinge_normals = option.choice ("on", "off");
    else if (arg == "--bend-test")
      o.bend_noise_test = option.choice ("noise", "share");
    else if (arg == "--assign")
    {
      const std::string v = value ();
      if (v == "edges")
        o.assignment = pcl::rspd::FinalAssignment::Edges;
      else if (v == "tails")
        o.assignment = pcl::rspd::FinalAssignment::Tails;
      else if (v == "all")
        o.assignment = pcl::rspd::FinalAssignment::All;
      else if (v == "none")
        o.assignment = pcl::rspd::FinalAssignment::None;
      else
        throw UsageError{"--assign needs 'edges', 'tails', 'all' or 'none' (got '" + v + "')"};
    }
    else if (arg == "--threads" || arg == "-t")
    {
      const std::string v = value ();
      if (!parseInteger (v, 1, 1024, o.threads))
        throw UsageError{"--threads needs an integer from 1 to 1024 (got '" + v + "')"};
    }
    else
      throw UsageError{"unknown option '" + arg + "'"};
  }
  if (o.demo && !o.input.empty ())
    throw UsageError{"give either INPUT or --demo, not both"};
  if (o.input.empty ())
    o.demo = true;
  // The labelled cloud may replace its input (it is written atomically), a CSV or PNG may not.
  for (const std::string* out : {&o.planes_csv, &o.png})
    if (!out->empty () && *out == o.input)
      throw UsageError{"'" + *out + "' is the input file; refusing to overwrite it with a CSV or PNG"};
  return o;
}

/** \brief Seconds since \a start. */
double
secondsSince (const std::chrono::steady_clock::time_point& start)
{
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
}

/** \brief The plane's [a b c d], from the coefficients or, failing that, from normal and centre. */
Eigen::Vector4d
planeOf (const pcl::RobustPlane& p)
{
  if (p.coefficients.values.size () >= 4)
    return Eigen::Vector4d (p.coefficients.values[0], p.coefficients.values[1], p.coefficients.values[2],
                            p.coefficients.values[3]);
  return Eigen::Vector4d (p.normal.x (), p.normal.y (), p.normal.z (), -p.normal.dot (p.center));
}

/** \brief The --planes table: one row per plane, label i = i-th plane (largest first). */
std::string
planesCsv (const std::vector<pcl::RobustPlane>& planes)
{
  std::string csv = "label,a,b,c,d,points,cx,cy,cz,extent_u,extent_v,mdp,mnd\n";
  char line[512];
  for (std::size_t i = 0; i < planes.size (); ++i)
  {
    const pcl::RobustPlane& p = planes[i];
    const Eigen::Vector4d c = planeOf (p);
    std::snprintf (line, sizeof (line), "%zu,%.9g,%.9g,%.9g,%.9g,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", i + 1,
                   c[0], c[1], c[2], c[3], p.indices.indices.size (), p.centroid.x (), p.centroid.y (),
                   p.centroid.z (), p.rect_size[0], p.rect_size[1], p.mdp, p.mnd);
    csv += line;
  }
  return csv;
}

/** \brief Report a bad input or output on one line of stderr. \return exit status 1 */
int
fail (const std::string& message)
{
  std::fprintf (stderr, "rspd_segment: error: %s\n", message.c_str ());
  return 1;
}

/** \brief Read (or generate), detect, summarise, write. \return exit status */
int
run (const Options& o)
{
  const auto log = [&] (const char* format, auto... args) {
    if (o.verbose)
    {
      std::fprintf (stderr, "[rspd_segment] ");
      std::fprintf (stderr, format, args...);
      std::fputc ('\n', stderr);
    }
  };
  std::string error;

  // Fail before the (possibly long) detection if an output cannot be written.
  for (const std::string* out : {&o.output, &o.planes_csv, &o.png})
    if (!out->empty () && !rspd_tools::checkWritable (*out, error))
      return fail (error);

  // --- read
  auto t0 = std::chrono::steady_clock::now ();
  rspd_tools::LoadedCloud cloud;
  std::string source;
  if (o.demo)
  {
    log ("generating the demo scene 'room'");
    pcl::rspd::Scene scene = pcl::rspd::makeScene ("room", pcl::rspd::SceneOptions ());
    rspd_tools::makeLoadedCloud (scene.cloud, cloud);
    source = "demo scene 'room' (" + std::to_string (scene.num_planes) + " planes in the ground truth)";
  }
  else
  {
    log ("reading %s", o.input.c_str ());
    if (!rspd_tools::loadCloud (o.input, cloud, error))
      return fail (error);
    source = o.input + " (" + cloud.format;
    if (cloud.blob.height > 1)
      source += ", organized " + std::to_string (cloud.blob.width) + "x" + std::to_string (cloud.blob.height);
    if (cloud.normals)
      source += ", with normals";
    source += ")";
  }
  const double t_read = secondsSince (t0);
  const std::size_t n = cloud.size ();
  const std::size_t valid = rspd_tools::countFinite (*cloud.xyz);
  log ("read: %.3f s, %zu points, %zu finite", t_read, n, valid);
  if (n == 0)
    return fail ((o.demo ? std::string ("demo scene") : o.input) + ": the cloud has no points");
  if (valid == 0)
    return fail ((o.demo ? std::string ("demo scene") : o.input) + ": the cloud has no point with finite x, y and z");

  if (o.verbose && !o.depth_level_dither)
  {
    // A hint, not a change: a structured-light or stereo camera's depth levels make planes of their own.
    std::vector<Eigen::Vector3d> finite;
    finite.reserve (valid);
    for (const auto& p : *cloud.xyz)
      if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
        finite.emplace_back (p.x, p.y, p.z);
    const pcl::rspd::DepthLevels levels = pcl::rspd::findDepthLevels (
        finite, cloud.xyz->sensor_origin_.head<3> ().cast<double> (), pcl::rspd::viewingAxis (cloud.xyz->sensor_orientation_));
    if (levels.quantized)
      log ("depth levels: the depths along the camera's axis take %zu levels (a structured-light or stereo camera's); "
           "--depth-levels dither keeps their terraces from becoming planes", levels.distinct);
  }

  // --- detect: the class runs graph, normals, split and grow/merge; it reports each stage's time.
  t0 = std::chrono::steady_clock::now ();
  pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::Normal> seg;
  seg.setInputCloud (cloud.xyz);
  if (cloud.normals)
    seg.setInputNormals (cloud.normals);
  seg.setNumberOfNeighbours (o.k);
  seg.setNormalScale (o.normal_scale);
  seg.setGivenNormalCheck (o.given_normal_check);
  seg.setDepthLevelDither (o.depth_level_dither);
  seg.setCoplanarMerge (o.coplanar_merge);
  seg.setRimCellRetest (o.rim_retest);
  seg.setRimRetestUntilStable (o.rim_retest_until_stable);
  seg.setLeftRimRetest (o.left_retest);
  seg.setPositionPlanes (o.position_planes);
  seg.setPositionSurfaceParts (o.position_surfaces);
  seg.setPositionSurfaceNormals (o.position_normals);
  seg.setPositionBendBand (o.position_bend_band);
  seg.setPositionBendSlabs (o.position_bend_slabs);
  seg.setPositionJoinBeside (o.position_join);
  seg.setPositionSurfaceLadder (o.position_ladder);
  seg.setPositionLadderRungs (o.ladder_rungs);
  seg.setTailOdds (o.tail_odds);
  seg.setMemberGaps (o.member_gaps);
  seg.setRimBands (o.rim_bands);
  seg.setSurroundingClutter (o.surrounding_clutter);
  seg.setHingeNormalTurn (o.hinge_normals);
  seg.setFarMemberRelease (o.release);
  seg.setReleasedPlaneSeeding (o.released_planes);
  seg.setEdgeSides (o.edge_sides);
  seg.setEdgeCorners (o.edge_corners);
  seg.setEdgeWedges (o.edge_wedges);
  seg.setStepSides (o.step_sides);
  seg.setStepRegions (o.step_regions);
  seg.setThickCellJoin (o.thick_join);
  seg.setSmallPassThickCellJoin (o.small_thick_join);
  seg.setNoisySeedGroups (o.noisy_groups);
  seg.setNoisyLoneSeeds (o.noisy_lone);
  seg.setNoisyGroupLadder (o.noisy_ladder);
  seg.setNoisyGrownT2 (o.noisy_t2);
  seg.setThickCellsFollowNoisySeeds (o.thick_follow);
  seg.setSupportCheck (o.support);
  seg.setSupportClutter (o.support_clutter);
  seg.setFinalParts (o.final_parts);
  seg.setFinalRefit (o.final_refit);
  seg.setLeftNormalRefit (o.left_normals == LeftNormals::Trimmed);
  seg.setLeftNormalRefitOnGivenNormals (o.left_normals != LeftNormals::Pca);
  seg.setLeftNormalNarrowing (o.left_normals == LeftNormals::Auto);
  seg.setShiftedGrid (o.shifted_grid);
  seg.setConnectedParts (o.connected_parts);
  seg.setBentPlaneSplit (o.bent_split);
  seg.setLayerMerge (o.layer_merge);
  seg.setLayerSteps (o.layer_steps);
  seg.setStepSplit (o.step_split);
  seg.setAcrossStepCheck (o.across_steps);
  seg.setBentSideParentMnd (o.bent_side_mnd);
  seg.setBentNormalEdges (o.bent_normals);
  seg.setCurvedPlaneCheck (o.curved_check);
  seg.setLateCurvedCheck (o.late_curved);
  seg.setCurvedNormalTurn (o.curved_turn);
  seg.setCurvedFoldTwoSides (o.curved_fold_sides);
  seg.setCurvedTubeCheck (o.tube_check);
  seg.setCurvedSplitParts (o.curved_parts);
  seg.setBendNoiseTest (o.bend_noise_test);
  seg.setDropOutlierSeeds (o.drop_outlier_seeds);
  seg.setOutlierSeedRetest (o.retest_outlier_seeds);
  seg.setVolumeLayerCheck (o.volume_layers);
  seg.setFinalVolumeLayerCheck (o.final_volume_layers);
  seg.setInBandLayerCheck (o.in_band_layers);
  seg.setFlatLayers (o.flat_layers);
  seg.setSmallPlaneCompletion (o.small_completion);
  seg.setBoundedReestimation (o.bounded_reestimate);
  seg.setNoisyPlaneBentSplit (o.noisy_bent_split);
  seg.setNormalFit (o.trimmed_normals ? pcl::rspd::NormalFit::TrimmedPlane : pcl::rspd::NormalFit::Pca);
  seg.setEdgeAwareNormals (o.edge_normals);
  seg.setDetectionFrame (o.dominant_frame ? pcl::rspd::DetectionFrame::DominantPlanes
                                          : pcl::rspd::DetectionFrame::InputAxes);
  seg.setFinalAssignment (o.assignment);
  if (o.threads > 0)
    seg.setNumberOfThreads (static_cast<unsigned int> (o.threads));
  log ("detecting planes (k = %s, %s threads, %s normals)", o.k > 0 ? std::to_string (o.k).c_str () : "automatic",
       o.threads > 0 ? std::to_string (o.threads).c_str () : "default",
       cloud.normals ? "file"
                     : (o.normal_scale == pcl::rspd::NormalScale::Fixed
                            ? "estimated"
                            : (o.normal_scale == pcl::rspd::NormalScale::Adaptive ? "estimated, adaptive scale,"
                                                                                    : "estimated, automatic scale,")));
  // getPlanes runs the detection; segment () would only copy every plane's indices once more.
  const std::vector<pcl::RobustPlane>& planes = seg.getPlanes ();
  if (!seg.hasResult ())
    return fail ("plane detection failed on " + std::to_string (valid) + " finite points" +
                 (o.verbose ? std::string () : std::string (" (run with -v for details)")));
  const double t_detect = secondsSince (t0);
  const pcl::rspd::DetectorStatistics& stats = seg.getStatistics ();
  log ("detect: %.3f s, %zu planes (eps = %zu, k = %d, %zu cells tested, %zu seed patches (%zu dropped as outliers, %zu of them seeded again), %zu planes seeded by groups of thick cells, %zu noisy seeds' planes dropped as where a volume of points ends, %zu kept by the small-plane "
       "pass (%zu brought to eps by completion, %zu by groups of its thick cells, %zu by groups of its noisy seeds (%zu past the noise ladder's first step), thick cells collected again %zu times, %zu on the %zu left points' trimmed or narrowed normals, %zu on the shifted grid, %zu as faces beside a plane), %zu of its cells seeded by their inliers, %d grow-merge iterations, %zu re-estimations (%zu kept within T2), %zu merges, "
       "%zu far members released, %zu planes seeded by them and %zu given back, %zu planes split off, %zu dropped as curved (%zu tubes among them and the cut parts), %zu split at an edge (%zu cut parts dropped as curved, %zu joined again as one face; %zu noisy seeds' planes split before they were judged, %zu dropped once grown as failing T2), %zu split off at a step, %zu merged as layers, %zu across a step dropped, %zu dropped as where a volume of points ends (%zu as layers inside a denser plane's band), %zu edge samples moved (%zu inside corners), %zu kept outside edges and %zu released, %zu step samples moved in regions and %zu one at a time, %zu left beyond their members' spacing, %zu dropped as curved once given their tails, %zu beyond a rim released (%zu amid clutter as dense as their plane), %zu joined to their plane by no chain of its points released and %zu planes split off at the end, %zu planes found by position among what was left, %zu planes left below eps dropped%s)",
       t_detect, planes.size (), seg.getResolvedMinPatchSize (), seg.getNumberOfNeighboursUsed (), stats.cells_tested, stats.seed_patches,
       stats.outlier_seeds, stats.retested_seeds, stats.joined_seeds, stats.volume_layers, stats.small_seeds, stats.small_completed, stats.small_joined_seeds, stats.small_noisy_groups, stats.small_ladder_seeds, stats.thick_rebound, stats.small_seeds_trimmed, stats.left_refitted, stats.small_seeds_shifted, stats.small_seeds_beside, stats.rim_seeds, stats.iterations, stats.reestimations, stats.kept_estimates, stats.merges, stats.released,
       stats.released_planes, stats.restored, stats.split_planes, stats.curved_planes, stats.curved_tubes, stats.bent_planes, stats.curved_parts, stats.bent_joined, stats.noisy_bent_planes, stats.noisy_past_t2, stats.steps_split, stats.layers_merged, stats.across_steps, stats.final_volume_layers, stats.in_band_layers, stats.edge_moved + stats.edge_cornered, stats.edge_cornered, stats.edge_outside, stats.edge_released, stats.step_region_moved, stats.step_moved, stats.member_gap_refused, stats.late_curved_planes, stats.unsupported, stats.clutter_released, stats.final_strays, stats.final_split, stats.position_planes, stats.below_epsilon, stats.hit_iteration_cap ? ", iteration cap hit" : "");
  if (o.edge_normals)
    log ("edge-aware normals: %zu of %zu narrowed to one face", stats.edge_narrowed_normals, valid);
  if (o.depth_level_dither)
    log ("depth levels: %s", stats.depth_levels ? (std::to_string (stats.depth_levels) + " distinct depths along the camera's axis, dithered within their bins").c_str ()
                                                : "the depths are not a camera's levels: samples as given");
  log ("stages: prepare %.3f s, neighbour graph %.3f s (%.1f MB), normals %.3f s%s, split %.3f s, grow/merge %.3f s, "
       "outputs %.3f s",
       stats.prepare_seconds, stats.graph_seconds, static_cast<double> (stats.graph_bytes) / 1e6, stats.normals_seconds,
       cloud.normals ? (stats.given_normals_blurred ? " (the file's blurred the faces a finer neighbourhood resolves: estimated again)"
                        : stats.given_normals_replaced ? " (the file's were noise at this scale: estimated again)" : " (from the file)") : "",
       stats.split_seconds, stats.grow_merge_seconds, stats.output_seconds);
  if (!stats.pass_seconds.empty ())
  {
    std::string passes;
    char buffer[32];
    for (const auto& pass : stats.pass_seconds)
    {
      std::snprintf (buffer, sizeof (buffer), " %.3f s", pass.second);
      passes += (passes.empty () ? "" : ", ") + pass.first + buffer;
    }
    log ("grow/merge passes: %s", passes.c_str ());
  }
  const pcl::rspd::GivenNormalCheck& given = seg.getGivenNormalCheckStatistics ();
  if (cloud.normals && given.fine_k > 0)
    log ("the file's normals against %d-neighbourhoods: %zu of %zu probes resolve a surface there, the file's "
         "normal fits %zu of those worse than %.0f times its plane's residual, %zu of the %zu the %d-neighbourhood's "
         "normal fits so%s",
         given.fine_k, given.fine_resolved, given.probes, given.fine_tilted, pcl::rspd::kBlurResidualRatio,
         given.graph_and_given_tilted, given.graph_tilted, pcl::rspd::kPaperNeighbours,
         stats.given_normals_blurred ? " (estimated again)" : "");
  const pcl::rspd::NormalScaleStatistics& scales = seg.getNormalScaleStatistics ();
  if (!scales.samples_per_scale.empty ())
  {
    std::string per_scale;
    for (std::size_t s = 0; s < scales.samples_per_scale.size (); ++s)
      per_scale += (s ? " " : "") + std::to_string (scales.samples_per_scale[s]);
    log ("normal scales: %zu samples unresolved at k (%zu of them passes most neighbours do not share), %zu from a wider scale, %zu "
         "unresolved at every scale%s; per scale (k-neighbourhood among every 2^s-th sample): %s; resolved when "
         "lambda0/lambda1 < %.3f",
         scales.unresolved_at_k, scales.chance_resolved, scales.widened (), scales.unresolved,
         scales.widened_scales ? "" : " (no wider scale searched)", per_scale.c_str (), scales.isotropic_ratio);
  }

  // Label i = i-th plane; the class returns planes largest first.
  std::vector<std::uint32_t> labels (n, 0);
  std::size_t assigned = 0;
  for (std::size_t i = 0; i < planes.size (); ++i)
    for (const pcl::index_t idx : planes[i].indices.indices)
      if (idx >= 0 && static_cast<std::size_t> (idx) < n && labels[idx] == 0)
      {
        labels[idx] = static_cast<std::uint32_t> (i + 1);
        ++assigned;
      }

  // --- summary
  std::printf ("input: %s\n", source.c_str ());
  std::printf ("points: %zu\n", n);
  std::printf ("valid points: %zu\n", valid);
  std::printf ("planes: %zu\n", planes.size ());
  std::printf ("points in planes: %zu (%.1f %% of valid)\n", assigned,
               100.0 * static_cast<double> (assigned) / static_cast<double> (valid));
  if (!planes.empty ())
    std::printf ("%5s %10s  %-30s %12s\n", "label", "points", "normal (a, b, c)", "d");
  const std::size_t shown = std::min<std::size_t> (planes.size (), 20);
  for (std::size_t i = 0; i < shown; ++i)
  {
    // + 0.0 turns -0 into 0 for display.
    const Eigen::Vector4d c = planeOf (planes[i]) + Eigen::Vector4d::Zero ();
    std::printf ("%5zu %10zu  (%8.5f, %8.5f, %8.5f) %12.6g\n", i + 1, planes[i].indices.indices.size (), c[0], c[1],
                 c[2], c[3]);
  }
  if (planes.size () > shown)
    std::printf ("  ... and %zu smaller planes\n", planes.size () - shown);
  std::fflush (stdout);

  // --- write
  t0 = std::chrono::steady_clock::now ();
  if (!o.output.empty ())
  {
    log ("writing %s", o.output.c_str ());
    if (!rspd_tools::writeLabeledCloud (o.output, cloud, labels, error))
      return fail (error);
  }
  if (!o.planes_csv.empty ())
  {
    log ("writing %s", o.planes_csv.c_str ());
    if (!rspd_tools::writeFileAtomically (o.planes_csv, planesCsv (planes), error))
      return fail (error);
  }
  if (!o.png.empty ())
  {
    log ("rendering %s (%dx%d)", o.png.c_str (), o.png_width, o.png_height);
    if (!rspd_tools::renderPng (*cloud.xyz, labels, o.png, o.png_width, o.png_height, error))
      return fail (error);
  }
  log ("write: %.3f s", secondsSince (t0));
  return 0;
}
} // namespace

int
main (int argc, char** argv)
{
  Options options;
  try
  {
    options = parseArguments (argc, argv);
  }
  catch (const UsageError& e)
  {
    std::fprintf (stderr, "rspd_segment: %s\n%s\n", e.message.c_str (), kUsage);
    return 2;
  }
  if (options.help)
  {
    std::printf ("%s\n\n%s", kUsage, kHelp);
    return 0;
  }
  // PCL's own messages would add lines after ours for the same problem; show them only with -v.
  pcl::console::setVerbosityLevel (options.verbose ? pcl::console::L_INFO : pcl::console::L_ALWAYS);
  try
  {
    return run (options);
  }
  catch (const std::bad_alloc&)
  {
    return fail ("out of memory");
  }
  catch (const std::exception& e)
  {
    return fail (e.what ());
  }
  catch (...)
  {
    return fail ("unexpected error");
  }
}
