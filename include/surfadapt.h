/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file surfadapt.h
 * @brief surfadapt: anisotropic adaptation of evolving triangulated surfaces.
 *
 * The only public header of the library. It is plain C (C99) and can be included
 * from C++ as is. The library adapts the explicit interface mesh of a running
 * simulation: the host hands over vertex coordinates and triangles and the
 * velocity of every vertex; surfadapt moves the surface and re-meshes it so that
 * volume, area and sharp features survive severe deformation. The algorithms are
 * those of X. Jiao, A. Colombi, X. Ni and J. C. Hart, "Anisotropic Mesh
 * Adaptation for Evolving Triangulated Surfaces".
 *
 * @par Use with a moving interface
 * Per time step of the host: (1) move the surface with sfa_advect() (a velocity
 * callback, RK4) or sfa_set_velocities() and sfa_move(), repeating while `dt_taken` is
 * less than what is left of the step; (2) sfa_smooth(s, 1); (3) every few steps (the
 * paper: 4), or at once after a step the fold control had to cut to less than half,
 * sfa_adapt(), then read the new mesh (sfa_get_counts(), sfa_get_mesh()) and fields.
 * Smoothing and adaptation keep the volume of every closed component (each bubble, each
 * drop on its own) to round-off, except where the correction that restores it would fold a
 * triangle or carry one sheet through another, or the component has no smooth vertex:
 * ::SFA_MEASURE_VOLUME_LEFT then says how far a volume was left. The tool's
 * `surfadapt enright` and `surfadapt vortex` follow exactly this schedule.
 *
 * @par Coordinates
 * The library computes in double precision with every |coordinate| at most 1e50 and a
 * mesh that spans at least 1e-50 (the diagonal of its bounding box). Its geometry is made
 * of products of up to six coordinate differences (areas, volumes, the fold tests and fold
 * times); within this range none of them overflows, and none of the mesh's own size
 * underflows. sfa_set_mesh() refuses a mesh outside it, and sfa_move() and sfa_advect() a
 * step that would leave it; a host whose units put its surface outside scales it. Volumes
 * (the measure, and those the volume correction keeps) are summed about the centre of each
 * closed component, so that a surface far from the origin keeps them to as many digits as
 * its coordinates give its shape.
 *
 * @par Conventions
 * - Counts and indices are `int32_t`; coordinates, velocities, times and field
 *   values are `double`, in the host's own (consistent) units.
 * - Arrays are flat and interleaved: `xyz[3*i+k]`, `tris[3*t+k]`, `vel[3*i+k]`,
 *   `values[ncomp*i+c]`.
 * - Triangles are counter-clockwise seen from outside: the right-hand normal
 *   points out of a closed surface.
 * - Every pointer the host passes is only read (or, for outputs, written) during
 *   the call; the library never keeps it. Strings the library returns are owned
 *   by the library (see each function for how long they stay valid).
 * - Every function that can fail returns a status from ::sfa_status.
 *   No function aborts, exits, prints, or lets a C++ exception escape.
 * - **Nothing lost**: after any failed call the surface (mesh, velocities, fields,
 *   parameters) is exactly as before, and sfa_last_error() says what was wrong.
 * - **Threads**: no global mutable state. Different handles may be used from
 *   different threads at the same time; one handle by one thread at a time.
 *   Inside a call, per-vertex and per-edge loops run on OpenMP threads
 *   (::SFA_PARAM_THREADS, default OpenMP's own setting); called from inside the host's
 *   own parallel region they follow OpenMP's nesting settings (by default they run on the
 *   calling thread alone). Results are bit-identical for any number of threads.
 */
#ifndef SURFADAPT_H
#define SURFADAPT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Major version of the library (incompatible changes). */
#define SFA_VERSION_MAJOR 1
/** Minor version of the library (compatible additions). */
#define SFA_VERSION_MINOR 1
/** Patch version of the library (fixes). */
#define SFA_VERSION_PATCH 0
/** Version of the binary interface this header describes; see sfa_get_api(). */
#define SFA_ABI_VERSION 1

/** Status returned by every function that can fail. */
enum sfa_status {
    SFA_OK = 0,           /**< Success. */
    SFA_ERR_ARGUMENT = 1, /**< Null pointer, negative count, buffer too small, unknown key, value out of range. */
    SFA_ERR_MESH = 2,     /**< The mesh given is not acceptable (index out of range, degenerate or duplicate
                               triangle, non-manifold edge or vertex, inconsistent orientation, non-finite
                               coordinate or one outside the range the library computes in, unreferenced
                               vertex). */
    SFA_ERR_STATE = 3,    /**< Call out of order, e.g. no mesh set yet. */
    SFA_ERR_NUMERIC = 4,  /**< Non-finite velocity or field value; a step that cannot be taken without folding. */
    SFA_ERR_MEMORY = 5,   /**< An allocation failed. */
    SFA_ERR_INTERNAL = 6  /**< A bug (an invariant check failed) or a capability not implemented yet.
                               The surface is still as it was. */
};

/* The last sentence of each key's documentation below ("Unit, range; default value.") is
   worded exactly as the library's range table and its messages word it
   (src/adapt/parameters.cpp); tests/unit/unit_constant_lists.cpp fails when they differ. */
/**
 * Keys of the tunable parameters, all of them `double`.
 *
 * Angles are in degrees. Parameters that are lengths are given as ratios to the
 * desired edge length l (::SFA_PARAM_EDGE_LENGTH), so that they follow l.
 * Greek letters refer to the paper (§3.1 and §4.3); the defaults are the paper's.
 * Parameters survive sfa_set_mesh().
 *
 * The last sentence of each key gives its unit, the values sfa_set_param() accepts and
 * its default, e.g. "Degrees, in (0, 60]; default 15.": a parenthesis marks an end that
 * is not itself accepted, a bracket one that is; "a flag" accepts 0 and 1 only, "a whole
 * number" no fractions. sfa_get_param_bounds() gives the ends at run time.
 */
enum sfa_param {
    /** Desired edge length l. 0 means the mean edge length of the mesh last given to
        sfa_set_mesh(). Length units, >= 0; default 0. */
    SFA_PARAM_EDGE_LENGTH = 0,
    /** 1: the paper's anisotropic adaptation; 0: isotropic adaptation with the same
        operations (identity metric), for comparison. A flag, 0 or 1; default 1. */
    SFA_PARAM_ANISOTROPIC = 1,
    /** Ridge threshold chi_c on lambda2/lambda1 as the angle f(chi) = 2 atan(sqrt(chi))
        (§3.1). A vertex whose quadric has lambda2/lambda1 >= chi_c is a feature vertex.
        Degrees, in (0, 180); default 45. */
    SFA_PARAM_RIDGE_ANGLE = 2,
    /** Corner threshold chi_r on lambda3/lambda1 as an angle (§3.1). A vertex with
        lambda3/lambda1 >= chi_r is a corner. Degrees, in (0, 180); default 20. */
    SFA_PARAM_CORNER_ANGLE = 3,
    /** Lower eigenvalue bound psi_l = lambda1 tan^2(theta/2) of the metric (eq. 12), as
        the angle theta; the default is §4.3's tan^2(4 deg). Degrees, in (0, 180);
        default 8. */
    SFA_PARAM_METRIC_MIN_ANGLE = 4,
    /** Upper eigenvalue bound psi_u of the metric (eq. 12) as an angle; the default is
        §4.3's tan^2(15 deg). Must exceed ::SFA_PARAM_METRIC_MIN_ANGLE when used.
        Degrees, in (0, 180); default 30. */
    SFA_PARAM_METRIC_MAX_ANGLE = 5,
    /** L / l: an edge longer than L that is the longest of its triangles is split
        ("absolute longness", §4.1). A ratio to l, > 0; default 1.5. */
    SFA_PARAM_SPLIT_LENGTH_RATIO = 6,
    /** s / l: relative-longness splitting (§4.1) only where the shortest edge of the
        incident triangles is at least s; the default is §4.3's sqrt(psi_l/psi_u).
        A ratio to l, > 0; default tan(4 deg)/tan(15 deg) = 0.2610. */
    SFA_PARAM_SPLIT_SHORTEST_RATIO = 7,
    /** S / l: "absolute small triangle" contraction threshold (§4.2); the default is
        §4.3's S = R l. A ratio to l, > 0; default 0.5. */
    SFA_PARAM_CONTRACT_LENGTH_RATIO = 8,
    /** r: "relative shortness" contraction ratio (§4.2). Two feature vertices (corners or
        ridge vertices) nearer than r l count as one feature: their edge may be contracted
        although that joins two corners or ridge curves (a cusp squeezed by the flow).
        Where both are near a facing sheet (the two sides of a sheet thinner than an edge),
        so do two nearer than 2 r l across a needle (an angle below ::SFA_PARAM_SMALL_ANGLE
        opposite their edge): the cusps at the rim of such a sheet.
        A ratio, in (0, 1); default 0.1. */
    SFA_PARAM_CONTRACT_SHORT_RATIO = 9,
    /** R: "relative small triangle" contraction ratio (§4.2). A ratio, in (0, 1);
        default 0.5. */
    SFA_PARAM_CONTRACT_SMALL_RATIO = 10,
    /** theta_s: "absolute small angle" contraction threshold (§4.2, §4.3). Degrees,
        in (0, 60]; default 15. */
    SFA_PARAM_SMALL_ANGLE = 11,
    /** theta_l: "relative longness" splitting threshold (§4.1, §4.3). Degrees,
        in [60, 180); default 160. */
    SFA_PARAM_LARGE_ANGLE = 12,
    /** Fraction of the time to the first fold that sfa_move() and sfa_advect() take
        at most; see sfa_move(). A fraction, in (0, 1]; default 0.5. */
    SFA_PARAM_FOLD_SAFETY = 13,
    /** What sfa_set_mesh() does with vertices that no triangle uses: 0 rejects the mesh
        with ::SFA_ERR_MESH naming the first one; 1 drops them and keeps the other
        vertices in their order (so vertex i of the result is the i-th referenced vertex
        of the input). A flag, 0 or 1; default 0. */
    SFA_PARAM_DROP_UNREFERENCED = 14,
    /** Feature detection safeguard: a vertex where a ridge curve turns by more than this
        angle is a corner, so that ridge vertices lie on curves that are locally straight
        or gently bent. Degrees, in (0, 180); default 40. */
    SFA_PARAM_RIDGE_TURN_ANGLE = 15,
    /** Anisotropic edge flipping (§3.3) changes the surface only where it is nearly flat:
        an edge is flipped only if the angle between the normals of its two triangles, and
        of the two triangles after the flip, is at most this. Ridge and boundary edges are
        never flipped. Degrees, in (0, 180); default 20. */
    SFA_PARAM_FLIP_DIHEDRAL_ANGLE = 16,
    /** Threads of the per-vertex and per-edge loops (OpenMP): 0 uses OMP_NUM_THREADS
        when it is set, else the CPUs the process may run on at the time of the call (its
        affinity mask, read at every call, so that an MPI rank bound to one core uses one
        thread); n >= 1 uses at most n, so that an MPI host can keep one thread per rank.
        Results never depend on it. Threads, a whole number in [0, 4096]; default 0. */
    SFA_PARAM_THREADS = 17,
    /** Denoising weight w (paper §5.1, §5.2.2); 0 is off. Each smoothing sweep
        (sfa_smooth(), and those of sfa_adapt()) then also moves every smooth vertex
        along its normal n by w/4 n.(U_v - mean of U_q over its neighbours q), with U the
        umbrella vector (mean of the neighbours minus the vertex): a step of bi-Laplacian
        normal diffusion, which flattens jagged fans (noise at the scale of an edge) and
        barely moves smoothly curved ones; features never move. Each closed component's
        enclosed volume is restored after each sweep (::SFA_PARAM_VOLUME_CORRECTION), so
        the motion removes noise without shrinking the body; open ones are not corrected. For flows that grow noise,
        like the second half of the Enright test. A weight, in [0, 1]; default 0. */
    SFA_PARAM_DENOISE = 18,
    /** The most passes of repair and optimization one sfa_adapt() call makes; fewer if a
        pass changes the connectivity around at most 1 in 100 vertices. A host that adapts
        every few steps of a flow sets 1: the second pass of a call changes only about 1 in
        200 vertices but costs as much as the first, and what one pass leaves is picked up
        by the next call. Passes, a whole number in [1, 100]; default 8. */
    SFA_PARAM_ADAPT_PASSES = 19,
    /** 1: sfa_adapt() and sfa_smooth() do not pass the surface through itself where a
        sheet is thinner than an edge (see sfa_adapt()); 0: they do not check. The check
        costs little where the surface is nowhere thin (finding the thin places, about
        3 % of an adaptation), and more where much of it is: about a sixth of the Enright
        test's whole run (10.9 s against 9.3 s without it, two cores; see the README). A
        host whose surface cannot thin out may set 0. A flag, 0 or 1; default 1. */
    SFA_PARAM_CROSSING_GUARD = 20,
    /** 1: after their own operations, sfa_smooth() (after each sweep) and sfa_adapt() give
        every closed component (bubble, drop) its enclosed volume back, each on its own by
        an offset of its smooth vertices along their normals: no volume moves from one
        component to another, and open components are not corrected. 0: no correction, so
        that what the operations alone do to the volumes can be seen. Either way
        ::SFA_MEASURE_VOLUME_CORRECTION reports how far the operations left a volume. Where
        the offset would fold a triangle or carry it through another sheet (a thin slab, a
        coarse cone after strong motion), the corners of those triangles are held and the
        rest of the component takes the volume back. The correction is withheld from a
        component with no smooth vertex, or where a few such rounds do not settle it: it
        keeps its shape, and its volume change is reported by ::SFA_MEASURE_VOLUME_LEFT. A
        flag, 0 or 1; default 1. */
    SFA_PARAM_VOLUME_CORRECTION = 21,
    /** How fast the desired edge length of a size field (sfa_set_size_field()) may change
        over the surface: before each sfa_adapt() the sizes are lowered where needed so
        that along the mesh l grows by at most (gradation - 1) times the distance
        travelled, l_v <= l_w + (gradation - 1) |x_v - x_w|; neighbouring edges of the
        desired length then differ by at most this factor (MMG's "hgrad"). Where the host
        asks for fine edges it gets them; the coarse side starts coarsening a short way
        off. Without a size field it has no effect. A ratio, > 1; default 1.5. */
    SFA_PARAM_SIZE_GRADATION = 22,
    /** Absolute shortness, a contraction criterion added to those of §4.2: an edge shorter
        than this ratio of l in both physical and metric space (eq. 4), and the shortest of
        its triangles, is contracted. The paper's criteria stop coarsening once every
        triangle's longest edge reaches S = ::SFA_PARAM_CONTRACT_LENGTH_RATIO l, so that a
        mesh finer than asked kept a mean edge of about S (0.53 l) instead of l; with this
        criterion the edges settle between it and L = ::SFA_PARAM_SPLIT_LENGTH_RATIO l from
        either side. Measured in metric space it leaves the short edges across a ridge or a
        tight curve, which the anisotropic metric asks for; it also leaves edges between two
        feature vertices (ridge curves keep their vertices) and edges at a vertex near a
        facing sheet (see ::SFA_PARAM_CROSSING_GUARD), where fewer vertices would let a later
        step carry one side through the other. 0: the paper's criteria alone.
        A ratio to l, in [0, 1); default 0.6. */
    SFA_PARAM_SHORT_EDGE_RATIO = 23,
    /** 1: sfa_move() and sfa_advect() also cut dt_taken so that no two triangles that share
        no vertex meet during the step. A pair may close at most half of its gap per call,
        measured across a plane that separates the two at the start and moves with them;
        this is conservative (a pair is never let touch, though it may be stopped short of
        where it would meet) and decided for every pair whose boxes, swept over the step,
        overlap. Two sheets that keep approaching are thus stopped apart; once they are
        closer than a millionth of their edge length the call fails with ::SFA_ERR_NUMERIC
        naming the two triangles, the gap and the time, the surface as it was. A pair that
        touches within the rounding of its coordinates may slide along its contact or
        open; if the step's positions, each coordinate rounded on its own, would still
        carry one through the other, the call fails the same way, naming the pair. Pairs
        that already meet when the call begins are not limited. Neighbours (sharing a vertex)
        are left to the fold control. The search costs most where a step carries vertices
        across many edge lengths: with it the Enright run (steps of about 4 edge lengths)
        and the vortex run with T = 2 take about 1.3 times as long, on one thread or two
        (see the README). 0: motion is cut only against folding. Off by default for that
        cost, and because without topology change a flow that brings two sheets together
        (the vortex flow with T = 6) would stop there.
        ::SFA_PARAM_TOPOLOGY_CHANGE turns it on as well, and adds contact: see there.
        A flag, 0 or 1; default 0. */
    SFA_PARAM_COLLISION_SAFE_MOTION = 24,
    /** 1: the surface may change its topology, as bubbles coalesce and drops break up.
        Each sfa_adapt() call first merges two sheets that face each other closer than the
        merge distance (::SFA_PARAM_MERGE_DISTANCE) across the outer phase (two drops that
        meet), or nearer than a quarter of it across the inner phase (a bubble's walls
        pressed together; a merely thin bubble stays whole): the two triangles of the nearest edge
        of each go, and a short tube of eight triangles joins the two holes (two bubbles
        become one, a film tears, or a sheet gains a handle; events of one call are at
        least two desired edge lengths apart). Then it cuts every neck or filament that contraction has
        thinned to a loop of three edges shorter than the merge distance, closing both
        sides with a triangle (one drop becomes two). Both are checked with exact
        predicates and undone where they would make the surface cross itself (or leave a
        triangle flat to round-off); vertices the host fixed and the ends of required edges
        take no part. A closed component less than two merge distances across is removed
        (::SFA_MEASURE_DROPS_REMOVED), unless nothing else is left. The
        adaptation that follows
        shapes the new triangles. Motion (sfa_move(), sfa_advect()) is then collision-safe
        as with ::SFA_PARAM_COLLISION_SAFE_MOTION, so that sheets meet here instead of
        passing through each other, with contact: two triangles that would stop the step
        while nearer than a twentieth of their longest edge (sheets not merged, such as a sheet
        folded flat onto itself, its layers too few triangles apart for a tube) are in
        contact, and instead of cutting the step their corners move together, each group
        of corners that contacts join taking the mean of its velocities (an inelastic
        impact zone). The step is cut only as far as the other pairs and the fold control
        require. ::SFA_MEASURE_MERGES, ::SFA_MEASURE_PINCHES and
        ::SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE tell what the last call did; the components
        (sfa_get_components()) tell which bubbles became which, and the vertex origins
        (sfa_get_vertex_origins()) where each vertex came from. 0: the topology never
        changes. A flag, 0 or 1; default 0. */
    SFA_PARAM_TOPOLOGY_CHANGE = 25,
    /** The merge distance of ::SFA_PARAM_TOPOLOGY_CHANGE, as a ratio of the local desired
        edge length l: sheets nearer than it merge, necks thinner than it are cut.
        A ratio to l, in (0, 10]; default 0.5. */
    SFA_PARAM_MERGE_DISTANCE = 26,
    /** The desired edge length where a sheet is thinner than an edge, as a ratio of the
        local l: each sfa_adapt() asks for this ratio times l (or times the host's size
        field, sfa_set_size_field()) at the vertices near a facing sheet, where the two
        sides of a sheet or of a narrow gap come nearer than their edges (those the
        crossing guard watches, ::SFA_PARAM_CROSSING_GUARD, whether or not it is on), graded
        like a size field (::SFA_PARAM_SIZE_GRADATION). So the mesh follows a sheet as it
        thins instead of letting a triangle span it, where it would have to bend round
        something smaller than itself (the vortex flow with T = 6 makes such sheets for
        most of its period; see doc/flows.md). The host's own size field is not changed. 1
        asks for nothing finer. A ratio to l, in (0, 1]; default 1. */
    SFA_PARAM_THIN_SHEET_EDGE_RATIO = 27
};

/** Quantities for sfa_measure(). */
enum sfa_measure_quantity {
    /** Signed enclosed volume, sum over triangles of a.(b x c)/6 (divergence theorem;
        positive for a closed surface with outward normals), for each closed component
        about the centre of its bounding box (the same value, without the digits lost
        far from the origin). For open components the same sum about the origin, which
        depends on the origin. Length units cubed. */
    SFA_MEASURE_VOLUME = 0,
    /** Total surface area, length units squared. */
    SFA_MEASURE_AREA = 1,
    /** Smallest interior angle of any triangle, degrees. */
    SFA_MEASURE_MIN_ANGLE = 2,
    /** Largest interior angle of any triangle, degrees. */
    SFA_MEASURE_MAX_ANGLE = 3,
    /** Mean length of the (undirected) edges, length units. */
    SFA_MEASURE_MEAN_EDGE_LENGTH = 4,
    /** Worst triangle aspect ratio: circumradius / (2 inradius), 1 for an equilateral
        triangle, growing without bound as a triangle degenerates. */
    SFA_MEASURE_MAX_ASPECT_RATIO = 5,
    /** Shortest edge length, length units. */
    SFA_MEASURE_MIN_EDGE_LENGTH = 6,
    /** Longest edge length, length units. */
    SFA_MEASURE_MAX_EDGE_LENGTH = 7,
    /** Largest angle between the normals of two triangles that share an edge, degrees:
        90 at a cube's edge, near 180 where the surface folds back on itself. */
    SFA_MEASURE_MAX_NORMAL_TURN = 8,
    /** Wall-clock seconds the successful sfa_smooth() and sfa_adapt() calls on this handle
        have spent, since sfa_create(), in surface analysis (quadrics, metric, features).
        With the next three, where the time of a run goes; the quantities that do not
        need a mesh set, and that differ from run to run. */
    SFA_MEASURE_SECONDS_ANALYSIS = 9,
    /** The same, in smoothing sweeps (with their field transfer and volume restoration). */
    SFA_MEASURE_SECONDS_SMOOTHING = 10,
    /** The same, in flipping passes. */
    SFA_MEASURE_SECONDS_FLIPPING = 11,
    /** The same, in splitting and contraction passes. */
    SFA_MEASURE_SECONDS_REPAIR = 12,
    /** Pairs of triangles that share no vertex yet intersect (touching counts): 0 unless
        the surface passes through itself, as where it was folded over or two parts
        collided. A sharp edge or cusp, however near 180 its ::SFA_MEASURE_MAX_NORMAL_TURN,
        counts nothing. Costs about a sort of the triangles. */
    SFA_MEASURE_SELF_INTERSECTIONS = 13,
    /** The largest relative volume change |dV| / V of any closed component that the
        operations of the last sfa_smooth() (any of its sweeps) or sfa_adapt() call made,
        before the correction of ::SFA_PARAM_VOLUME_CORRECTION took it back: how close the
        operations themselves come to conserving each volume. 0 before the first such call;
        it needs no mesh set. Dimensionless. */
    SFA_MEASURE_VOLUME_CORRECTION = 14,
    /** How many merges of two sheets (::SFA_PARAM_TOPOLOGY_CHANGE) the last sfa_adapt()
        call made; 0 before the first. */
    SFA_MEASURE_MERGES = 15,
    /** How many necks or filaments the last sfa_adapt() call cut; 0 before the first. */
    SFA_MEASURE_PINCHES = 16,
    /** The volume the merges and pinches of the last sfa_adapt() call made or destroyed,
        each event's |change| summed (a tube encloses the thin gap it bridges; a cut neck
        loses the sliver between its two closing triangles). Length units cubed; 0 before
        the first call. The adaptation after the events keeps each new component's volume
        as the events left it. */
    SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE = 17,
    /** How many closed components the last sfa_adapt() call removed because they were
        less than two merge distances across (::SFA_PARAM_TOPOLOGY_CHANGE): drops below
        what the mesh resolves, such as the satellite a pinch leaves between two ends.
        Their volume counts in ::SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE, and their face-field
        integrals go with them. 0 before the first call. */
    SFA_MEASURE_DROPS_REMOVED = 18,
    /** The largest relative volume change |dV| / V of any closed component that the last
        sfa_smooth() or sfa_adapt() call left: 0 when every volume was restored; the change
        of a component the correction was withheld from (::SFA_PARAM_VOLUME_CORRECTION),
        or, with the correction off, ::SFA_MEASURE_VOLUME_CORRECTION. A host that needs the
        volumes exactly checks it after each call. 0 before the first such call; it needs
        no mesh set. Dimensionless. */
    SFA_MEASURE_VOLUME_LEFT = 19,
    /** The share of the area, in [0, 1], of the triangles near which the surface turns by
        more than a right angle within the triangle's own size: the surface reached from
        the triangle across edges, through triangles nearer to its centroid than its
        longest edge, holds two triangles whose normals are more than 90 degrees apart.
        There the mesh does not resolve the surface: the rim of a sheet or a filament
        thinner than the triangles, a fold, or a crease sharper than a right angle (a
        sharp edge the host means to keep counts too). The far side of a thin sheet is not
        reached across it, so a well-meshed film counts only at its rim. 0 where every
        turn is resolved (a sphere 15 edges round turns by 24 degrees an edge). A host
        watches it to see where its interface has become thinner than its mesh: finer
        edges there (::SFA_PARAM_THIN_SHEET_EDGE_RATIO, sfa_set_size_field()) or merging
        (::SFA_PARAM_TOPOLOGY_CHANGE). Dimensionless. Costs a walk over a few dozen
        triangles from each (about 0.1 s for 200k triangles on two cores). */
    SFA_MEASURE_UNRESOLVED_AREA = 20,
    /** Smallest interior angle of any triangle outside the places of
        ::SFA_MEASURE_UNRESOLVED_AREA, degrees; 180 if there is none. A triangle that must
        bend round something smaller than itself has no good angles wherever its corners
        go; this is ::SFA_MEASURE_MIN_ANGLE of the others. Costs what
        ::SFA_MEASURE_UNRESOLVED_AREA costs. */
    SFA_MEASURE_MIN_ANGLE_RESOLVED = 21
};

/** One adaptive surface. Opaque; create with sfa_create(), free with sfa_destroy(). */
typedef struct sfa_surface sfa_surface;

/**
 * Velocity field evaluated by the host, in batches (see sfa_advect()).
 * @param ctx  the host's pointer given to sfa_advect(), passed back unchanged.
 * @param n    number of points.
 * @param xyz  `3*n` coordinates of the points (read only, owned by the library,
 *             valid during the call only).
 * @param t    time at which to evaluate.
 * @param vel  `3*n` velocities to write (owned by the library, valid during the call only).
 *             Every value must be finite.
 */
typedef void (*sfa_velocity_fn)(void *ctx, int32_t n, const double *xyz, double t, double *vel);

/* ---------------------------------------------------------------- library */

/** @return the library version as `"MAJOR.MINOR.PATCH"`; a static string. */
const char *sfa_version_string(void);

/** @return ::SFA_ABI_VERSION of the library loaded (which is 1). */
int sfa_abi_version(void);

/**
 * The version of the library loaded as one number, for comparisons: MAJOR * 10000 +
 * MINOR * 100 + PATCH, e.g. 10203 for 1.2.3 (MINOR and PATCH stay below 100). A host
 * compiled against this header finds a library at least as new as the header when
 * `sfa_version_number() >= SFA_VERSION_MAJOR * 10000 + SFA_VERSION_MINOR * 100 +
 * SFA_VERSION_PATCH`.
 * @return the version number; the same as sfa_version_string() says.
 */
int sfa_version_number(void);

/**
 * Describes a status code.
 * @param status a status code, usually one of ::sfa_status.
 * @return a static, never NULL description of a status code, e.g. "SFA_ERR_MESH: the
 *         mesh given is not acceptable"; unknown codes give "unknown status".
 */
const char *sfa_status_string(int status);

/* ------------------------------------------------------ lifecycle, errors */

/**
 * Creates an empty surface with default parameters. Besides the mesh and its fields, a
 * surface keeps the working memory of its analyses from one sfa_smooth() or sfa_adapt()
 * call to the next (about 270 bytes per vertex), so that a flow does not allocate it on
 * every step; sfa_destroy() frees it.
 * @param out receives the new handle (owned by the caller, free with sfa_destroy());
 *            set to NULL on failure.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (`out` is NULL), ::SFA_ERR_MEMORY.
 */
int sfa_create(sfa_surface **out);

/**
 * Frees a surface and everything it owns.
 * @param s the surface, invalid afterwards; NULL is a no-op.
 */
void sfa_destroy(sfa_surface *s);

/**
 * Why the last call on a surface failed.
 * @param s the surface, or NULL.
 * @return a description of why the last call on `s` failed, naming the offending input
 *         (e.g. "triangle 17 uses vertex 2041, but there are 2000 vertices"), or "" after a
 *         successful call. Never NULL. Owned by `s`, valid until the next call on `s`.
 *         For `s == NULL` a static string.
 */
const char *sfa_last_error(const sfa_surface *s);

/* ------------------------------------------------------- mesh in and out */

/**
 * Replaces the mesh after validating it completely.
 *
 * Accepted: closed or open (bounded) orientable 2-manifold surfaces, possibly of
 * several components, consistently oriented. Rejected with ::SFA_ERR_MESH and a
 * message naming the element and the rule: no triangles, a non-finite coordinate,
 * a coordinate outside the range the library computes in (every |coordinate| at most
 * 1e50, and the mesh spanning at least 1e-50, the diagonal of its bounding box: see
 * "Coordinates" at the top), a vertex index out of range, a triangle that uses a vertex twice, a zero-area
 * triangle, two triangles on the same three vertices (in any order), an edge
 * shared by more than two triangles, two triangles that traverse their shared edge
 * in the same direction (inconsistent orientation), a vertex whose triangles form
 * more than one fan (bow-tie), and a vertex that no triangle uses (unless
 * ::SFA_PARAM_DROP_UNREFERENCED is 1). Messages count elements in the host's index base.
 *
 * Drops the velocities and fields of the previous mesh; keeps the parameters.
 *
 * @param s          the surface.
 * @param nverts     number of vertices, >= 0.
 * @param xyz        `3*nverts` coordinates (read only, not kept).
 * @param ntris      number of triangles, >= 0.
 * @param tris       `3*ntris` vertex indices, counter-clockwise seen from outside (read only, not kept).
 * @param index_base 0 if vertex indices start at 0 (C), 1 if they start at 1 (Fortran).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, negative count, index_base not 0 or 1),
 *         ::SFA_ERR_MESH, ::SFA_ERR_MEMORY.
 */
int sfa_set_mesh(sfa_surface *s, int32_t nverts, const double *xyz, int32_t ntris,
                 const int32_t *tris, int32_t index_base);

/**
 * Current numbers of vertices and triangles (0 and 0 before any mesh is set).
 * @param s      the surface.
 * @param nverts receives the vertex count (may be NULL if not wanted).
 * @param ntris  receives the triangle count (may be NULL if not wanted).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (`s` is NULL).
 */
int sfa_get_counts(const sfa_surface *s, int32_t *nverts, int32_t *ntris);

/**
 * Copies the current mesh out: dense (no holes), in a deterministic order. Before any
 * sfa_adapt(), the order is that of the mesh set (less dropped unreferenced vertices).
 * @param s             the surface.
 * @param vert_capacity number of vertices `xyz` has room for (it holds `3*vert_capacity` doubles).
 * @param xyz           receives `3*nverts` coordinates (owned by the caller).
 * @param tri_capacity  number of triangles `tris` has room for.
 * @param tris          receives `3*ntris` vertex indices (owned by the caller).
 * @param index_base    0 or 1, the base of the indices written.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, capacity too small: nothing written;
 *         bad index_base), ::SFA_ERR_STATE (no mesh set).
 */
int sfa_get_mesh(const sfa_surface *s, int32_t vert_capacity, double *xyz, int32_t tri_capacity,
                 int32_t *tris, int32_t index_base);

/* ------------------------------------------------------------ parameters */

/**
 * Sets one parameter (see ::sfa_param for keys, units, ranges and defaults).
 * @param s     the surface.
 * @param key   one of ::sfa_param.
 * @param value the new value, in the units of that key.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL handle, unknown key, non-finite or out-of-range value).
 */
int sfa_set_param(sfa_surface *s, int key, double value);

/**
 * Reads one parameter.
 * @param s     the surface.
 * @param key   one of ::sfa_param.
 * @param value receives the value (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, unknown key).
 */
int sfa_get_param(const sfa_surface *s, int key, double *value);

/**
 * The ends of the values sfa_set_param() accepts for one key (as zstd's
 * ZSTD_cParam_getBounds does for its parameters), in the key's unit (see ::sfa_param).
 * They are the closed hull of the accepted values: where the key's range is open at an
 * end (a parenthesis in its documentation, e.g. (0, 180) for ::SFA_PARAM_RIDGE_ANGLE),
 * that end is given but is itself rejected; an end without a bound is INFINITY (the
 * highest ::SFA_PARAM_EDGE_LENGTH, for one); a flag or whole-number key accepts only the
 * whole numbers between its ends. The answer is the same for every surface: it comes
 * from the table sfa_set_param() checks against.
 *
 * No surface is involved, so there is no sfa_last_error() message: the status alone
 * tells what was wrong.
 * @param key     one of ::sfa_param.
 * @param lowest  receives the lower end.
 * @param highest receives the upper end.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (unknown key, `lowest` or `highest` NULL; nothing
 *         written).
 */
int sfa_get_param_bounds(int key, double *lowest, double *highest);

/* ---------------------------------------------------------------- motion */

/**
 * Sets the velocity of every current vertex, used by sfa_move(). They stay set until
 * the next sfa_set_velocities() or sfa_set_mesh(); sfa_adapt() carries them to the new
 * vertices.
 * @warning The length of `vel` is taken to be 3 times the current vertex count, which
 * sfa_adapt() changes: an array sized for the mesh before it is read past its end. Prefer
 * sfa_set_velocities_checked(), which is told the count the array was made for.
 * @param s   the surface.
 * @param vel `3*nverts` velocity components, length units per time unit (read only, not kept).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer), ::SFA_ERR_STATE (no mesh),
 *         ::SFA_ERR_NUMERIC (a non-finite component; names the vertex), ::SFA_ERR_MEMORY.
 */
int sfa_set_velocities(sfa_surface *s, const double *vel);

/**
 * sfa_set_velocities() for an array made for `nverts` vertices: ::SFA_ERR_ARGUMENT, with
 * a message that says both counts, when the mesh has another number of vertices (a stale
 * array from before an sfa_adapt() call). Nothing else differs.
 * @param s      the surface.
 * @param nverts the number of vertices `vel` holds velocities for.
 * @param vel    `3*nverts` velocity components (read only, not kept).
 * @return as sfa_set_velocities(), and ::SFA_ERR_ARGUMENT for another vertex count.
 */
int sfa_set_velocities_checked(sfa_surface *s, int32_t nverts, const double *vel);

/**
 * Moves every vertex by one explicit Euler step with the velocities set:
 * x += dt_taken * v. Connectivity and vertex count do not change.
 *
 * Fold control: under linear motion the normal n(t) of each triangle is quadratic in t,
 * and the triangle turns over at the first positive root of n(0).n(t) = 0. The step is
 * cut to `dt_taken = min(dt, f * t_fold)` with f = ::SFA_PARAM_FOLD_SAFETY, t_fold the
 * earliest such root over all triangles. The host sub-steps with the rest (dt - dt_taken).
 * A step the fold control would cut below 1e-12 dt is refused (::SFA_ERR_NUMERIC, naming
 * the triangle that turns over first and when; nothing moved): the fold is then nearer
 * than the surface can advance to, as when a bubble shrinks to a point (each step would
 * halve the time left to the fold, and the host's time would stop advancing while every
 * call returned ::SFA_OK). 10^12 sub-steps would be needed to finish dt.
 *
 * @param s        the surface.
 * @param dt       the step wanted, time units, finite and > 0.
 * @param dt_taken receives the step taken, 1e-12 dt <= *dt_taken <= dt.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, dt not finite or <= 0),
 *         ::SFA_ERR_STATE (no mesh, or no velocities set), ::SFA_ERR_NUMERIC (the fold
 *         control allows less than 1e-12 dt; or even the largest safe step leaves a triangle
 *         flat or turned over once rounded: the fold is closer than round-off resolves; or
 *         the step would carry a vertex outside the range
 *         the library computes in, or shrink the mesh below it: see "Coordinates" at the
 *         top; nothing moved), ::SFA_ERR_MEMORY.
 */
int sfa_move(sfa_surface *s, double dt, double *dt_taken);

/**
 * Advances the surface by one classic fourth-order Runge–Kutta step through a velocity
 * field that the host evaluates in batches of all vertices (four calls of `f` per attempt).
 * The same fold control as sfa_move() applies to the RK4 displacement: if the step
 * would fold a triangle it is retried with a shorter one, and `*dt_taken < dt`; as there,
 * a step that would have to be cut below 1e-12 dt is refused.
 * Connectivity and vertex count do not change; the velocities set by
 * sfa_set_velocities() are not touched.
 *
 * @param s        the surface.
 * @param f        the velocity field (must not be NULL); must write finite values.
 * @param ctx      passed to `f` unchanged (may be NULL; never dereferenced by the library).
 * @param t        time at the start of the step.
 * @param dt       the step wanted, finite and > 0.
 * @param dt_taken receives the step taken, 1e-12 dt <= *dt_taken <= dt.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT, ::SFA_ERR_STATE (no mesh), ::SFA_ERR_NUMERIC
 *         (`f` wrote a non-finite value, or no step of at least 1e-12 dt avoids folding, or
 *         the step would leave the range the library computes in, as for sfa_move();
 *         nothing moved), ::SFA_ERR_MEMORY.
 */
int sfa_advect(sfa_surface *s, sfa_velocity_fn f, void *ctx, double t, double dt, double *dt_taken);

/* ------------------------------------------------------------ adaptation */

/**
 * Anisotropic vertex redistribution (paper §3.2): `iterations` Jacobi sweeps. In each, the
 * surface is analysed once (sfa_get_feature_ranks(), sfa_get_vertex_frames()); every smooth
 * vertex moves in its tangent plane towards the point that balances its edges' lengths in
 * the anisotropic metric and is lifted onto a quadratic surface fitted to its neighbours;
 * every ridge or boundary vertex moves along the circle through itself and its two ridge
 * neighbours (the line, where they are collinear); corners do not move. A smooth vertex
 * whose balancing step would be shorter than 2.5 % of its mean (metric) edge stays where it
 * is: its fan is settled, and a mesh that is settled everywhere is left exactly as it is
 * (the sweeps do not drift it off the surface). A vertex whose
 * move would fold a triangle stays put for that sweep, and so do the corners of a triangle
 * that would pass through another part of the surface (::SFA_PARAM_CROSSING_GUARD, on by
 * default: where a sheet is thinner than an edge, its other side is that near; such places
 * are found by the last sfa_adapt(), or by this call if the mesh was set since). After
 * each sweep every closed component gets its own enclosed volume back by an offset of its
 * smooth vertices along their normals (a correction in the primary space), so smoothing
 * never changes a bubble's volume (::SFA_PARAM_VOLUME_CORRECTION switches the correction
 * off; ::SFA_MEASURE_VOLUME_CORRECTION tells how far the sweeps alone moved a volume, and
 * ::SFA_MEASURE_VOLUME_LEFT how far a volume stays moved where the correction is withheld).
 * Fields are interpolated at the new positions. Connectivity and vertex order do not
 * change, so host arrays stay valid.
 * @param s          the surface.
 * @param iterations number of sweeps, >= 0.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (also: metric min angle not below max angle),
 *         ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_smooth(sfa_surface *s, int32_t iterations);

/**
 * The full adaptation (paper §3–§4) towards the edge length ::SFA_PARAM_EDGE_LENGTH (0:
 * the mean edge length of the mesh last given to sfa_set_mesh()). Features are detected
 * once and kept through the call. Then, up to ::SFA_PARAM_ADAPT_PASSES times (default
 * 8), until a pass changes the connectivity around at most 1 in 100 vertices: edge splitting (§4.1), edge
 * contraction (§4.2), anisotropic edge flipping (§3.3) and two smoothing sweeps (as
 * sfa_smooth()), each after a fresh analysis. Every
 * threshold is a parameter (§4.3). Every closed component ends with the enclosed volume it
 * started with (to round-off), each on its own (::SFA_PARAM_VOLUME_CORRECTION; where the
 * correction is withheld, ::SFA_MEASURE_VOLUME_LEFT says by how much it did not). Corners never move; ridge vertices stay on their ridge
 * curves; boundaries stay boundaries. With ::SFA_PARAM_CROSSING_GUARD (on by default),
 * splits, contractions, flips and sweeps are kept from passing the surface through itself:
 * where a sheet is thinner than an edge (the filaments of a strong vortex), an operation
 * that would carry a triangle through a triangle of the other side is not made. (Motion can still bring two sheets nearer than the mesh resolves:
 * sfa_measure() ::SFA_MEASURE_SELF_INTERSECTIONS counts the crossings.)
 *
 * Vertex and triangle counts change and vertices are renumbered: read the mesh back with
 * sfa_get_counts() and sfa_get_mesh(). A call that splits or contracts edges returns the
 * vertices in the order of a space-filling curve through the surface, and the triangles
 * in the order of their first vertex, so that neighbours lie close in memory (in the
 * host's arrays too); a call that only flips and smooths keeps the numbering. Fields and velocities follow: a new or moved vertex gets the values
 * interpolated (barycentrically) at its position in the old triangle it lies over, so
 * that a field linear on a flat region stays exactly linear. A vertex put on a straight
 * ridge edge is interpolated along that edge only, so values do not mix across the ridge
 * (on a curved ridge, to second order in the edge length); a vertex merged into a corner
 * or ridge vertex keeps that vertex's values. The result is the same
 * for any number of threads and on every run. One call typically changes the density by
 * up to a factor of four; call it again to go further.
 * @param s the surface.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (metric min angle not below max angle),
 *         ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY, ::SFA_ERR_INTERNAL (a broken
 *         result was caught; please report it). After any failure the surface, its
 *         fields and velocities are as before.
 */
int sfa_adapt(sfa_surface *s);

/* -------------------------------------------------------------- analysis */

/**
 * Feature rank of every current vertex: 0 smooth, 1 ridge, 2 corner (paper §2.2, §3.1).
 * A vertex is a feature candidate when its quadric's lambda2/lambda1 reaches the ridge
 * threshold (or lambda3/lambda1 the corner threshold); ridge edges join two candidates across
 * a dihedral angle of at least ::SFA_PARAM_RIDGE_ANGLE, and boundary edges are ridge edges.
 * Then ranks follow the ridge curves: a vertex on exactly two ridge edges is a ridge vertex,
 * unless the curve turns there by more than ::SFA_PARAM_RIDGE_TURN_ANGLE; a vertex where
 * curves end or meet (one, three or more ridge edges) is a corner; so is an isolated corner
 * candidate (a cone's tip). Everything else is smooth. The answer does not depend on vertex
 * or triangle order, position, orientation or scale.
 * @param s        the surface.
 * @param capacity number of `int32_t` that `ranks` has room for, >= nverts.
 * @param ranks    receives nverts ranks (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, capacity too small: nothing written),
 *         ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_get_feature_ranks(const sfa_surface *s, int32_t capacity, int32_t *ranks);

/**
 * Per-vertex results of the quadric analysis (paper §2.2, §3.1) for hosts and viewers.
 * Any output may be NULL when not wanted.
 * @param s               the surface.
 * @param capacity        number of vertices the outputs have room for, >= nverts.
 * @param normals         receives `3*nverts` unit normals: the quadric's first eigenvector e1,
 *                        oriented outward (along the vertex's area-weighted face normal).
 * @param long_directions receives `3*nverts` unit tangent vectors along which the anisotropic
 *                        metric wants triangles long (its smaller eigenvalue, e3 of the quadric).
 * @param aspect_ratios   receives `nverts` metric aspect ratios sqrt(m_max / m_min) >= 1, at most
 *                        sqrt(psi_u / psi_l) (eq. 12); 1 everywhere in isotropic mode.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL handle, capacity too small: nothing written),
 *         ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_get_vertex_frames(const sfa_surface *s, int32_t capacity, double *normals, double *long_directions,
                          double *aspect_ratios);

/**
 * The ridge edges found by feature detection (boundary edges included), each as its two
 * vertex indices, smaller first, sorted; the same edges that sfa_get_feature_ranks() counts.
 * @param s          the surface.
 * @param capacity   number of edges `edges` has room for (it holds `2*capacity` indices).
 * @param edges      receives `2*count` vertex indices; may be NULL to ask for the count only.
 * @param count      receives the number of ridge edges (always, when not NULL).
 * @param index_base 0 or 1, the base of the indices written.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL handle, `edges` given with capacity too small:
 *         edges not written; bad index_base), ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_get_ridge_edges(const sfa_surface *s, int32_t capacity, int32_t *edges, int32_t *count,
                        int32_t index_base);

/**
 * Measures the current surface.
 * @param s        the surface.
 * @param quantity one of ::sfa_measure_quantity.
 * @param value    receives the value (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, unknown quantity), ::SFA_ERR_STATE (no mesh).
 */
int sfa_measure(const sfa_surface *s, int quantity, double *value);

/* ----------------------------------------------------------- host control */

/**
 * A desired edge length for every current vertex (e.g. the flow solver's local grid
 * spacing), in place of ::SFA_PARAM_EDGE_LENGTH: where it is set, the thresholds of mesh
 * repair (split, contract; paper §4.3) are those of the local l, the mean of an edge's
 * ends' values, while the anisotropic metric still shapes the triangles. Before each
 * sfa_adapt() the sizes are graded (::SFA_PARAM_SIZE_GRADATION) so that the mesh can
 * follow them smoothly. The sizes are carried through motion (each vertex keeps its own),
 * smoothing and adaptation (interpolated at new vertices; the grading stays) until
 * replaced, cleared, or dropped by sfa_set_mesh().
 * @warning `edge_length` is taken to hold one value per current vertex: prefer
 * sfa_set_size_field_checked().
 * @param s           the surface.
 * @param edge_length `nverts` lengths > 0, host length units (read only, not kept); NULL
 *                    clears the size field, and ::SFA_PARAM_EDGE_LENGTH applies again.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL handle; a value <= 0: names the vertex, in
 *         the numbering of the last sfa_set_mesh(); nothing changed), ::SFA_ERR_NUMERIC (a
 *         value not finite, as for the other fields: named the same way; nothing changed),
 *         ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_set_size_field(sfa_surface *s, const double *edge_length);

/**
 * sfa_set_size_field() for an array made for `nverts` vertices: ::SFA_ERR_ARGUMENT when
 * the mesh has another number of vertices. With `edge_length` NULL it clears, as
 * sfa_set_size_field() does.
 * @param s           the surface.
 * @param nverts      the number of vertices `edge_length` was made for.
 * @param edge_length `nverts` lengths > 0, or NULL (see sfa_set_size_field()).
 * @return as sfa_set_size_field(), and ::SFA_ERR_ARGUMENT for another vertex count.
 */
int sfa_set_size_field_checked(sfa_surface *s, int32_t nverts, const double *edge_length);

/**
 * Fixes vertices: sfa_smooth() and sfa_adapt() never move them (nor does the volume
 * correction) and never remove them: a contraction next to one keeps it where it is, and
 * an edge between two fixed vertices is never contracted. Edges at them may still be
 * split and flipped (use sfa_set_required_edges() to keep edges). Motion (sfa_move(),
 * sfa_advect()) still moves them with their velocities. They follow the renumbering of
 * sfa_adapt() and stay fixed until the next call, which replaces the whole set, or
 * sfa_set_mesh(), which drops it.
 * @param s          the surface.
 * @param count      number of vertices; 0 clears the set (`vertices` may then be NULL).
 * @param vertices   `count` vertex indices (read only, not kept); repeats are allowed.
 * @param index_base 0 or 1, the base of the indices.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer with count > 0, count < 0, bad
 *         index_base, an index that is not a vertex: names its position and value; nothing
 *         changed), ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_set_fixed_vertices(sfa_surface *s, int32_t count, const int32_t *vertices, int32_t index_base);

/**
 * Requires edges: sfa_smooth() and sfa_adapt() keep them exactly, never splitting,
 * flipping or contracting them, and their ends are fixed (as by sfa_set_fixed_vertices(),
 * on top of that set), e.g. a contact line or the seam with a structure. They follow the
 * renumbering of sfa_adapt() until the next call, which replaces the whole set, or
 * sfa_set_mesh().
 * @param s          the surface.
 * @param count      number of edges; 0 clears the set (`edges` may then be NULL).
 * @param edges      `2*count` vertex indices, `edges[2*i]` and `edges[2*i+1]` the ends of
 *                   edge i, in either order (read only, not kept).
 * @param index_base 0 or 1, the base of the indices.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer with count > 0, count < 0, bad
 *         index_base, an index that is not a vertex, a pair that is not an edge of the mesh:
 *         names the pair; nothing changed), ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_set_required_edges(sfa_surface *s, int32_t count, const int32_t *edges, int32_t index_base);

/**
 * Attaches densities to the triangles: `ncomp` values per triangle, each a density per
 * unit area (host units), e.g. a surfactant concentration or a surface charge.
 * sfa_smooth() and sfa_adapt() keep the integral of each component over each connected
 * component of the surface exactly (to round-off): every change of the mesh remaps the
 * densities of the faces it replaces onto the new faces by their overlap, in a plane
 * chart of the change's own fan, so that a constant density stays nearly constant (it
 * absorbs the small change of a curved fan's area) and a varying one is smeared no more
 * than the remap must. Motion (sfa_move(), sfa_advect()) leaves the densities as they are
 * (a stretched triangle keeps its density, not its integral). Face field ids are their
 * own sequence, apart from sfa_add_field()'s; fields are dropped by sfa_set_mesh().
 * @warning `values` is taken to hold `ncomp*ntris` values for the current triangle count,
 * which sfa_adapt() changes: prefer sfa_add_face_field_checked().
 * @param s        the surface.
 * @param ncomp    components per triangle, >= 1.
 * @param values   `ncomp*ntris` densities, `values[ncomp*t+c]` (read only, not kept); finite.
 * @param field_id receives the id: 0 for the first face field of a mesh, then 1, 2, ...
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, ncomp < 1), ::SFA_ERR_STATE (no mesh),
 *         ::SFA_ERR_NUMERIC (a non-finite value; names the triangle), ::SFA_ERR_MEMORY.
 */
int sfa_add_face_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id);

/**
 * sfa_add_face_field() for an array made for `ntris` triangles: ::SFA_ERR_ARGUMENT when
 * the mesh has another number of triangles.
 * @param s        the surface.
 * @param ntris    the number of triangles `values` was made for.
 * @param ncomp    components per triangle, >= 1.
 * @param values   `ncomp*ntris` densities (read only, not kept); finite.
 * @param field_id receives the id (see sfa_add_face_field()).
 * @return as sfa_add_face_field(), and ::SFA_ERR_ARGUMENT for another triangle count.
 */
int sfa_add_face_field_checked(sfa_surface *s, int32_t ntris, int32_t ncomp, const double *values,
                               int32_t *field_id);

/**
 * Copies a face field's densities on the current triangles out.
 * @param s        the surface.
 * @param field_id an id from sfa_add_face_field().
 * @param capacity number of doubles `values` has room for, >= ncomp*ntris.
 * @param values   receives `ncomp*ntris` densities (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, unknown id, capacity too small:
 *         nothing written), ::SFA_ERR_STATE (no mesh).
 */
int sfa_get_face_field(const sfa_surface *s, int32_t field_id, int32_t capacity, double *values);

/**
 * Replaces a face field's densities on the current triangles, e.g. after the host has
 * advanced the quantity they hold over a time step (a surfactant transported and diffused
 * on the surface). From then on sfa_smooth() and sfa_adapt() keep the integral of the new
 * values.
 * @param s        the surface.
 * @param field_id an id from sfa_add_face_field().
 * @param ntris    the number of triangles `values` was made for: the mesh's count.
 * @param values   `ncomp*ntris` densities of the field's ncomp (read only, not kept); finite.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, unknown id, `ntris` not the mesh's),
 *         ::SFA_ERR_STATE (no mesh), ::SFA_ERR_NUMERIC (a non-finite value; names the
 *         triangle), ::SFA_ERR_MEMORY; on any error the field is unchanged.
 */
int sfa_set_face_field(sfa_surface *s, int32_t field_id, int32_t ntris, const double *values);

/**
 * Where each current vertex came from: the triangle of the mesh as it was just before the
 * last sfa_smooth() or sfa_adapt() call (in that mesh's numbering, as sfa_get_mesh() gave
 * it then) over which the vertex lay right after the call, and its barycentric
 * coordinates there. With it a host or a coupling library carries data of its own through
 * the call: the value at vertex i is the sum over k of `barycentric[3*i+k]` times the
 * old value at corner k of `triangle[i]`. The coordinates are those of the vertex's
 * closest point on that triangle: exact where the old surface was flat (the position is
 * reproduced to round-off), first order where it was curved. Each triangle is found by a
 * short walk over the old mesh from a triangle the call followed the vertex to, so the
 * answer costs a few triangles per vertex, paid only when asked. Later motion does not
 * change the answer (it is about the vertex's place right after the call); the old mesh
 * is kept for it until the next such call or sfa_set_mesh().
 * @param s           the surface.
 * @param capacity    number of vertices the outputs have room for, >= nverts.
 * @param triangle    receives `nverts` triangle indices of the old mesh, from `index_base`.
 * @param barycentric receives `3*nverts` coordinates, each in [0, 1], the three of a vertex
 *                    adding up to 1.
 * @param index_base  0 or 1, the base of the triangle indices written.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, capacity too small, bad index_base:
 *         nothing written), ::SFA_ERR_STATE (no mesh, or no sfa_smooth() or sfa_adapt()
 *         since the mesh was set), ::SFA_ERR_MEMORY.
 */
int sfa_get_vertex_origins(const sfa_surface *s, int32_t capacity, int32_t *triangle, double *barycentric,
                           int32_t index_base);

/* ------------------------------------------------------------- components */

/**
 * The number of connected components of the current mesh (vertices joined by edges):
 * the bubbles, drops and sheets of an interface. Each closed component keeps its own
 * enclosed volume through sfa_smooth() and sfa_adapt() (see ::SFA_PARAM_VOLUME_CORRECTION).
 * @param s     the surface.
 * @param count receives the number (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer), ::SFA_ERR_STATE (no mesh),
 *         ::SFA_ERR_MEMORY.
 */
int sfa_get_component_count(const sfa_surface *s, int32_t *count);

/**
 * The component of every current vertex, 0 to count - 1, numbered in the order in which
 * each component's first vertex comes in sfa_get_mesh() order (so the numbering is
 * deterministic; it is 0-based whatever the index base).
 * @param s                the surface.
 * @param capacity         number of ints `vertex_component` has room for (at least the
 *                         vertex count).
 * @param vertex_component receives one id per vertex (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, capacity too small: nothing
 *         written), ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_get_components(const sfa_surface *s, int32_t capacity, int32_t *vertex_component);

/**
 * sfa_measure() restricted to one component (as numbered by sfa_get_components()): every
 * quantity that measures the mesh (volume, area, angles, edge lengths, aspect ratio,
 * normal turn, self-intersections within the component).
 * @param s         the surface.
 * @param component 0 to the component count - 1.
 * @param quantity  one of ::sfa_measure_quantity.
 * @param value     receives the value (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, unknown quantity, a quantity of the
 *         calls rather than of the mesh (the seconds, ::SFA_MEASURE_VOLUME_CORRECTION), no
 *         such component), ::SFA_ERR_STATE (no mesh), ::SFA_ERR_MEMORY.
 */
int sfa_measure_component(const sfa_surface *s, int32_t component, int quantity, double *value);

/* ---------------------------------------------------------- vertex fields */

/**
 * Attaches host data to the vertices: `ncomp` doubles per vertex, which follow every
 * operation that moves or creates vertices. Fields are dropped by sfa_set_mesh().
 * @param s        the surface.
 * @param ncomp    components per vertex, >= 1.
 * @param values   `ncomp*nverts` values, `values[ncomp*i+c]` (read only, not kept); finite.
 * @param field_id receives the id of the field: 0 for the first field of a mesh, then 1, 2, ...
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, ncomp < 1), ::SFA_ERR_STATE (no mesh),
 *         ::SFA_ERR_NUMERIC (a non-finite value; names the vertex), ::SFA_ERR_MEMORY.
 */
int sfa_add_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id);

/**
 * sfa_add_field() for an array made for `nverts` vertices: ::SFA_ERR_ARGUMENT when the
 * mesh has another number of vertices (sfa_add_field() would read past the array's end).
 * @param s        the surface.
 * @param nverts   the number of vertices `values` holds values for.
 * @param ncomp    components per vertex, >= 1.
 * @param values   `ncomp*nverts` values (read only, not kept); finite.
 * @param field_id receives the id of the field.
 * @return as sfa_add_field(), and ::SFA_ERR_ARGUMENT for another vertex count.
 */
int sfa_add_field_checked(sfa_surface *s, int32_t nverts, int32_t ncomp, const double *values, int32_t *field_id);

/**
 * Copies a field's values on the current vertices out.
 * @param s        the surface.
 * @param field_id an id from sfa_add_field().
 * @param capacity number of doubles `values` has room for, >= ncomp*nverts.
 * @param values   receives `ncomp*nverts` values (owned by the caller).
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, unknown id, capacity too small:
 *         nothing written), ::SFA_ERR_STATE (no mesh).
 */
int sfa_get_field(const sfa_surface *s, int32_t field_id, int32_t capacity, double *values);

/**
 * Replaces a field's values on the current vertices, e.g. after the host has advanced the
 * quantity it holds over a time step.
 * @param s        the surface.
 * @param field_id an id from sfa_add_field().
 * @param nverts   the number of vertices `values` was made for: the mesh's count.
 * @param values   `ncomp*nverts` values of the field's ncomp (read only, not kept); finite.
 * @return ::SFA_OK, ::SFA_ERR_ARGUMENT (NULL pointer, unknown id, `nverts` not the mesh's),
 *         ::SFA_ERR_STATE (no mesh), ::SFA_ERR_NUMERIC (a non-finite value; names the
 *         vertex), ::SFA_ERR_MEMORY; on any error the field is unchanged.
 */
int sfa_set_field(sfa_surface *s, int32_t field_id, int32_t nverts, const double *values);

/* ---------------------------------------------------------------- plugins */

/**
 * The function table of one ABI version, for hosts that `dlopen` the library and
 * resolve only sfa_get_api(). Members are in the order in which the functions were
 * added to the library: new members are only ever appended, and `struct_size` tells how
 * many there are.
 */
typedef struct sfa_api {
    uint32_t struct_size; /**< sizeof(sfa_api) of the library that filled the table. */
    uint32_t abi;         /**< The ABI version of the table, ::SFA_ABI_VERSION. */
    const char *(*version_string)(void);                      /**< sfa_version_string() */
    int (*abi_version)(void);                                 /**< sfa_abi_version() */
    const char *(*status_string)(int status);                 /**< sfa_status_string() */
    int (*create)(sfa_surface **out);                         /**< sfa_create() */
    void (*destroy)(sfa_surface *s);                          /**< sfa_destroy() */
    const char *(*last_error)(const sfa_surface *s);          /**< sfa_last_error() */
    int (*set_mesh)(sfa_surface *s, int32_t nverts, const double *xyz, int32_t ntris,
                    const int32_t *tris, int32_t index_base); /**< sfa_set_mesh() */
    int (*get_counts)(const sfa_surface *s, int32_t *nverts, int32_t *ntris); /**< sfa_get_counts() */
    int (*get_mesh)(const sfa_surface *s, int32_t vert_capacity, double *xyz, int32_t tri_capacity,
                    int32_t *tris, int32_t index_base);     /**< sfa_get_mesh() */
    int (*set_param)(sfa_surface *s, int key, double value);  /**< sfa_set_param() */
    int (*get_param)(const sfa_surface *s, int key, double *value); /**< sfa_get_param() */
    int (*set_velocities)(sfa_surface *s, const double *vel); /**< sfa_set_velocities() */
    int (*move)(sfa_surface *s, double dt, double *dt_taken); /**< sfa_move() */
    int (*advect)(sfa_surface *s, sfa_velocity_fn f, void *ctx, double t, double dt,
                  double *dt_taken);                          /**< sfa_advect() */
    int (*smooth)(sfa_surface *s, int32_t iterations);        /**< sfa_smooth() */
    int (*adapt)(sfa_surface *s);                             /**< sfa_adapt() */
    int (*get_feature_ranks)(const sfa_surface *s, int32_t capacity, int32_t *ranks); /**< sfa_get_feature_ranks() */
    int (*measure)(const sfa_surface *s, int quantity, double *value); /**< sfa_measure() */
    int (*add_field)(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id); /**< sfa_add_field() */
    int (*get_field)(const sfa_surface *s, int32_t field_id, int32_t capacity, double *values); /**< sfa_get_field() */
    int (*get_vertex_frames)(const sfa_surface *s, int32_t capacity, double *normals, double *long_directions,
                             double *aspect_ratios);          /**< sfa_get_vertex_frames() */
    int (*get_ridge_edges)(const sfa_surface *s, int32_t capacity, int32_t *edges, int32_t *count,
                           int32_t index_base);             /**< sfa_get_ridge_edges() */
    int (*get_param_bounds)(int key, double *lowest, double *highest); /**< sfa_get_param_bounds() */
    int (*version_number)(void);                              /**< sfa_version_number() */
    int (*get_component_count)(const sfa_surface *s, int32_t *count); /**< sfa_get_component_count() */
    int (*get_components)(const sfa_surface *s, int32_t capacity, int32_t *vertex_component); /**< sfa_get_components() */
    int (*measure_component)(const sfa_surface *s, int32_t component, int quantity,
                             double *value);                  /**< sfa_measure_component() */
    int (*set_velocities_checked)(sfa_surface *s, int32_t nverts,
                                  const double *vel);         /**< sfa_set_velocities_checked() */
    int (*add_field_checked)(sfa_surface *s, int32_t nverts, int32_t ncomp, const double *values,
                             int32_t *field_id);              /**< sfa_add_field_checked() */
    int (*set_size_field)(sfa_surface *s, const double *edge_length); /**< sfa_set_size_field() */
    int (*set_size_field_checked)(sfa_surface *s, int32_t nverts,
                                  const double *edge_length); /**< sfa_set_size_field_checked() */
    int (*set_fixed_vertices)(sfa_surface *s, int32_t count, const int32_t *vertices,
                              int32_t index_base);            /**< sfa_set_fixed_vertices() */
    int (*set_required_edges)(sfa_surface *s, int32_t count, const int32_t *edges,
                              int32_t index_base);            /**< sfa_set_required_edges() */
    int (*add_face_field)(sfa_surface *s, int32_t ncomp, const double *values,
                          int32_t *field_id);                 /**< sfa_add_face_field() */
    int (*add_face_field_checked)(sfa_surface *s, int32_t ntris, int32_t ncomp, const double *values,
                                  int32_t *field_id);         /**< sfa_add_face_field_checked() */
    int (*get_face_field)(const sfa_surface *s, int32_t field_id, int32_t capacity,
                          double *values);                    /**< sfa_get_face_field() */
    int (*get_vertex_origins)(const sfa_surface *s, int32_t capacity, int32_t *triangle, double *barycentric,
                              int32_t index_base);            /**< sfa_get_vertex_origins() */
    int (*set_field)(sfa_surface *s, int32_t field_id, int32_t nverts,
                     const double *values);                   /**< sfa_set_field() */
    int (*set_face_field)(sfa_surface *s, int32_t field_id, int32_t ntris,
                          const double *values);              /**< sfa_set_face_field() */
} sfa_api;

/**
 * The function table of one ABI version. A host that `dlopen`s `libsurfadapt.so.1`
 * resolves this one symbol and nothing else.
 * @param abi_version the ABI version wanted, normally ::SFA_ABI_VERSION.
 * @return the table (static, valid as long as the library is loaded), or NULL if this
 *         library does not provide that version.
 */
const sfa_api *sfa_get_api(uint32_t abi_version);

#ifdef __cplusplus
}
#endif

#endif /* SURFADAPT_H */
