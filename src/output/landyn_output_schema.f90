!> The result file's schema declared once (docs/output.md): every dataset's path, units, shape,
!! kind and meaning, in one table. The writer (landyn_schema_write, used by landyn_output and
!! landyn_provenance's callers) takes the units from the table and refuses a dataset that is not
!! in the table or whose kind or rank differ; `landyn_schema` prints the table as a JSON manifest, which landyn_post reads
!! (post/landyn_post/data/output_schema.json, checked against the build by CTest
!! `output_schema_manifest`) and which docs/output.md's dataset tables are checked against
!! (CTest `output_schema_docs`).
!!
!! Shapes are written as h5py reads them (C order), comma-separated: `n` output samples, `g` gears,
!! `s` struts per gear, `m` rows of /api/inputs, `k` primary honeycomb stages, `l` crush levels
!! of all struts, integers for fixed lengths; '' is a scalar. Fortran writes the reverse: x(3, n) reads as (n, 3).
module landyn_output_schema
  implicit none
  private

  public :: dataset_spec_t, output_datasets, result_schema_version, campaign_schema_version, find_dataset, spec_rank

  !> Version of the result-file schema, `MAJOR.MINOR` (docs/output.md, root attribute schema_version).
  character(len=*), parameter :: result_schema_version = '1.5'
  !> Layout of a campaign summary file (docs/campaign.md, root attribute schema_version), defined here
  !! (not in src/campaign, built only with MPI) so that the manifest carries it to landyn_post.
  character(len=*), parameter :: campaign_schema_version = 'landyn-campaign-1.0'

  !> One dataset of the schema.
  type :: dataset_spec_t
    character(len=48) :: path = ''          !! absolute dataset path [-]
    character(len=8) :: units = ''          !! value of its `units` attribute [-]
    character(len=8) :: shape = ''          !! shape symbols as h5py reads it, comma-separated; '' scalar [-]
    character(len=4) :: kind = ''           !! real, int, bool (logical) or text [-]
    character(len=16) :: components = ''    !! labels of the last axis (comma-separated; s = the strut names) [-]
    character(len=4) :: since = ''          !! schema version that added it [-]
    character(len=12) :: written = ''       !! always, with health (run-health checks), api inputs, summaries
                                            !! (campaign summaries only) [-]
    character(len=480) :: meaning = ''      !! what it holds (docs/output.md, the `description` attribute) [-]
  end type dataset_spec_t

  !> Datasets of section meta.
  type(dataset_spec_t), parameter :: ds_meta(*) = [ &
    dataset_spec_t('/meta/code_version', '-', '', 'text', '', '1.0', 'always', &
      'LANDYN version, e.g. `0.1.0`'), &
    dataset_spec_t('/meta/git_revision', '-', '', 'text', '', '1.0', 'always', &
      '`git describe` of the source tree at build time (in a campaign summary: of the code that ran the cases)'), &
    dataset_spec_t('/meta/writer_git_revision', '-', '', 'text', '', '1.0', 'summaries', &
      'campaign summaries only: `git describe` of the code that wrote the file'), &
    dataset_spec_t('/meta/build_type', '-', '', 'text', '', '1.0', 'always', &
      'CMake build type (`Release`, `Debug`, ...)'), &
    dataset_spec_t('/meta/compiler', '-', '', 'text', '', '1.0', 'always', &
      '`compiler_version()` of the compiler that built LANDYN'), &
    dataset_spec_t('/meta/compiler_flags', '-', '', 'text', '', '1.0', 'always', &
      'flags of the LANDYN sources as configured'), &
    dataset_spec_t('/meta/compiler_options', '-', '', 'text', '', '1.0', 'always', &
      '`compiler_options()` of the module that wrote the file'), &
    dataset_spec_t('/meta/date', '-', '', 'text', '', '1.0', 'always', &
      'time the file was written, ISO 8601 with UTC offset, e.g. `2026-11-22T10:15:00+00:00`'), &
    dataset_spec_t('/meta/command_line', '-', '', 'text', '', '1.0', 'always', &
      'the command that ran LANDYN'), &
    dataset_spec_t('/meta/deck_name', '-', '', 'text', '', '1.0', 'always', &
      'the input deck''s path, or `(built-in default)`'), &
    dataset_spec_t('/meta/deck_text', '-', '', 'text', '', '1.0', 'always', &
      'the input deck exactly as given (or `(none: built-in default input)`)'), &
    dataset_spec_t('/meta/resolved_input', '-', '', 'text', '', '1.0', 'always', &
      'the fully resolved input as a namelist deck: every variable of every group, defaults filled '// &
      'in, angles in degrees, every gear''s hard points written out in the lander frame. Feeding it '// &
      'back to `landyn` reproduces the run.'), &
    dataset_spec_t('/meta/units', '-', '', 'text', '', '1.0', 'always', &
      'the unit statement: `SI (m, kg, s, N, J); angles in deg; overload in g = 9.80665 m/s^2; '// &
      'global frame z down`')]

  !> Datasets of section model.
  type(dataset_spec_t), parameter :: ds_model(*) = [ &
    dataset_spec_t('/model/n_gears', '-', '', 'int', '', '1.4', 'always', &
      'number of gears g'), &
    dataset_spec_t('/model/n_struts', '-', 'g', 'int', '', '1.4', 'always', &
      'struts of each gear (3 for the tripod); where a gear has fewer than s, its rows of the (g, '// &
      's) arrays are 0'), &
    dataset_spec_t('/model/strut_names', '-', 's', 'text', '', '1.4', 'always', &
      'names of the struts along every strut axis s: `primary`, `secondary left`, `secondary '// &
      'right` for the tripod'), &
    dataset_spec_t('/model/mass_centre', 'm', '3', 'real', 'x,y,z', '1.4', 'always', &
      'the body''s mass centre, lander frame (`&lander mass_centre`)'), &
    dataset_spec_t('/model/gear_axes', '-', 'g,3,3', 'real', '', '1.4', 'always', &
      'gear i''s frame: row j of [i] is its axis x, y, z (j = 0, 1, 2) in lander axes, so the '// &
      'gear-to-lander rotation is its transpose; the lander frame turned about z by `&gears '// &
      'rotation(i)`'), &
    dataset_spec_t('/model/upper_joint', 'm', 'g,s,3', 'real', 'x,y,z', '1.4', 'always', &
      'upper joint of each strut on the body (a primary, b secondary left, c secondary right), '// &
      'lander frame'), &
    dataset_spec_t('/model/lower_joint', 'm', 'g,s,3', 'real', 'x,y,z', '1.4', 'always', &
      'lower end of each strut in the nominal (uncrushed) geometry: the footpad ball joint d of '// &
      'the primary, the lugs e and f of the secondaries on the primary''s outer tube; lander frame'), &
    dataset_spec_t('/model/strut_frame/x', '-', 'g,s,3', 'real', 'x,y,z', '1.4', 'always', &
      'x0 of each strut''s nominal frame, lander axes: the pin of its upper universal joint fixed '// &
      'to the body (e_y x z0 in the gear frame, normalised; e_x x z0 when nearly parallel)'), &
    dataset_spec_t('/model/strut_frame/y', '-', 'g,s,3', 'real', 'x,y,z', '1.4', 'always', &
      'y0 = z0 x x0 of each strut''s nominal frame, lander axes'), &
    dataset_spec_t('/model/strut_frame/z', '-', 'g,s,3', 'real', 'x,y,z', '1.4', 'always', &
      'z0 of each strut''s nominal frame, lander axes: the unit vector from its upper joint to its '// &
      'lower end. The primary''s orientation is R0 rot_x(t1) rot_y(t2), R0 = [x0 y0 z0] '// &
      '(docs/theory.md)'), &
    dataset_spec_t('/model/stroke_capacity', 'm', 'g,s,2', 'real', '', '1.4', 'always', &
      'stroke capacity of each strut''s buffer: [..., 0] toward + (primary shortening, secondary '// &
      'lengthening), [..., 1] toward - (secondary shortening) as a positive length; 0 where a '// &
      'strut has none'), &
    dataset_spec_t('/model/primary_stage_end', 'm', 'k', 'real', '', '1.4', 'always', &
      'ends of the primary honeycomb''s stages, stroke in shortening (k = `&primary_strut n_stages`)'), &
    dataset_spec_t('/model/terrain/height', 'm', 'g', 'real', '', '1.4', 'always', &
      'terrain plane under each footpad: its elevation at the global origin, up positive'), &
    dataset_spec_t('/model/terrain/slope', 'deg', 'g', 'real', '', '1.4', 'always', &
      'its slope angle'), &
    dataset_spec_t('/model/terrain/slope_direction', 'deg', 'g', 'real', '', '1.4', 'always', &
      'its uphill azimuth, from global +x toward +y'), &
    dataset_spec_t('/model/crush_levels/gear', '-', 'l', 'int', '', '1.5', 'always', &
      'the table of every strut''s crush levels, one row a level, ordered by gear, strut, level: '// &
      'the gear of the row, 0-based along the g axes'), &
    dataset_spec_t('/model/crush_levels/strut', '-', 'l', 'int', '', '1.5', 'always', &
      'the strut of the row, 0-based along the s axes'), &
    dataset_spec_t('/model/crush_levels/force', 'N', 'l', 'real', '', '1.5', 'always', &
      'the level: a constant force at which the strut''s buffer crushes, as an axial force '// &
      '(compression +, like `strut_force`), reported by its buffer law: each stage of the primary '// &
      'honeycomb (+), the secondary''s crush force in lengthening (-) and in shortening (+)'), &
    dataset_spec_t('/model/crush_levels/name', '-', 'l', 'text', '', '1.5', 'always', &
      'what the level is: `stage 1`, `stage 2`, ... (primary), `lengthening`, `shortening` '// &
      '(secondaries)'), &
    dataset_spec_t('/model/mass', 'kg', '', 'real', '', '1.5', 'always', &
      'total lander mass, legs included (`&lander mass`)'), &
    dataset_spec_t('/model/gravity', 'm/s^2', '', 'real', '', '1.5', 'always', &
      'gravitational acceleration along global +z (`&simulation gravity`)'), &
    dataset_spec_t('/model/friction/mu_static', '-', '', 'real', '', '1.5', 'always', &
      'static friction coefficient of the footpads (`&friction mu_static`)'), &
    dataset_spec_t('/model/friction/mu_dynamic', '-', '', 'real', '', '1.5', 'always', &
      'dynamic friction coefficient (`&friction mu_dynamic`)'), &
    dataset_spec_t('/model/touchdown/velocity', 'm/s', '3', 'real', 'x,y,z', '1.5', 'always', &
      'mass-centre velocity at t = 0, global frame, z down (`&initial_state velocity`)'), &
    dataset_spec_t('/model/touchdown/attitude', 'deg', '3', 'real', 'yaw,pitch,roll', '1.5', 'always', &
      'Z-Y-X Euler angles yaw, pitch, roll at t = 0 (`&initial_state attitude`)'), &
    dataset_spec_t('/model/touchdown/angular_rate', 'deg/s', '3', 'real', 'p,q,r', '1.5', 'always', &
      'body rates p, q, r at t = 0, lander axes (`&initial_state angular_rate`)'), &
    dataset_spec_t('/model/touchdown/clearance', 'm', '', 'real', '', '1.5', 'always', &
      'gap of the lowest footpad at t = 0 when `&initial_state position` is not given '// &
      '(`&initial_state clearance`)')]

  !> Datasets of section body.
  type(dataset_spec_t), parameter :: ds_body(*) = [ &
    dataset_spec_t('/timeseries/time', 's', 'n', 'real', '', '1.0', 'always', &
      'output time'), &
    dataset_spec_t('/timeseries/body/position', 'm', 'n,3', 'real', 'x,y,z', '1.0', 'always', &
      'lander-frame origin O_L (geometric centre), global frame, z down'), &
    dataset_spec_t('/timeseries/body/mass_centre_position', 'm', 'n,3', 'real', 'x,y,z', '1.0', 'always', &
      'mass centre, global frame (= position + R * `&lander mass_centre`)'), &
    dataset_spec_t('/timeseries/body/velocity', 'm/s', 'n,3', 'real', 'x,y,z', '1.0', 'always', &
      'mass-centre velocity, global frame (+z = descending), at the sample time (the integrators'' '// &
      'stored velocities lag half a step; the samples are synchronised)'), &
    dataset_spec_t('/timeseries/body/euler_angles', 'deg', 'n,3', 'real', 'yaw,pitch,roll', '1.0', 'always', &
      'Z-Y-X Euler angles yaw, pitch, roll (columns 0, 1, 2)'), &
    dataset_spec_t('/timeseries/body/angular_rate', 'deg/s', 'n,3', 'real', 'p,q,r', '1.0', 'always', &
      'body rates p, q, r about the lander x, y, z axes'), &
    dataset_spec_t('/timeseries/body/overload', 'g', 'n,3', 'real', 'x,y,z', '1.0', 'always', &
      '(a - g)/9.80665 at the mass centre in lander axes: what an accelerometer there reads. While '// &
      'the gears decelerate a descent the z component is **negative** (the specific force points '// &
      'up, -z in the z-down frame).'), &
    dataset_spec_t('/timeseries/body/overload_peak', 'g', 'n', 'real', '', '1.0', 'always', &
      'largest |overload| over every integration step since the previous sample, this one '// &
      'included: the stored history keeps every peak the summary reports (`max(overload_peak) = '// &
      '/summary/peak_overload`)')]

  !> Datasets of section gears.
  type(dataset_spec_t), parameter :: ds_gears(*) = [ &
    dataset_spec_t('/timeseries/gears/strut_length', 'm', 'n,g,s', 'real', 's', '1.0', 'always', &
      'joint-to-joint length: primary a-d, secondary left b-e, secondary right c-f'), &
    dataset_spec_t('/timeseries/gears/stroke', 'm', 'n,g,s', 'real', 's', '1.0', 'always', &
      'stroke in the Table 3 sense: primary shortening +, secondaries lengthening +'), &
    dataset_spec_t('/timeseries/gears/strut_force', 'N', 'n,g,s', 'real', 's', '1.0', 'always', &
      'axial buffer force, compression positive'), &
    dataset_spec_t('/timeseries/gears/strut_force_peak', 'N', 'n,g,s', 'real', 's', '1.0', 'always', &
      'largest |axial force| over every step since the previous sample (`max = '// &
      '/summary/peak_strut_force`)'), &
    dataset_spec_t('/timeseries/gears/footpad_position', 'm', 'n,g,3', 'real', 'x,y,z', '1.0', 'always', &
      'footpad ball joint d_i, global frame, z down'), &
    dataset_spec_t('/timeseries/gears/ground_force', 'N', 'n,g,3', 'real', 'x,y,z', '1.0', 'always', &
      'ground force acting on the footpad (normal + friction), global frame (its z component is '// &
      'negative: it pushes up)'), &
    dataset_spec_t('/timeseries/gears/normal_force', 'N', 'n,g', 'real', '', '1.0', 'always', &
      'normal contact force on the footpad, >= 0'), &
    dataset_spec_t('/timeseries/gears/normal_force_peak', 'N', 'n,g', 'real', '', '1.0', 'always', &
      'largest normal force over every step since the previous sample (`max = '// &
      '/summary/peak_normal_force`)'), &
    dataset_spec_t('/timeseries/gears/friction_force', 'N', 'n,g', 'real', '', '1.0', 'always', &
      'magnitude of the friction force on the footpad'), &
    dataset_spec_t('/timeseries/gears/penetration', 'm', 'n,g', 'real', '', '1.0', 'always', &
      'depth of the footpad joint below its local terrain plane, along the plane''s normal; '// &
      'negative = above the surface'), &
    dataset_spec_t('/timeseries/gears/slip_speed', 'm/s', 'n,g', 'real', '', '1.0', 'always', &
      'footpad speed tangential to its local surface')]

  !> Datasets of section loads.
  type(dataset_spec_t), parameter :: ds_loads(*) = [ &
    dataset_spec_t('/timeseries/gears/joint_force_a', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'force joint a puts on the body, lander axes'), &
    dataset_spec_t('/timeseries/gears/joint_force_b', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint b'), &
    dataset_spec_t('/timeseries/gears/joint_force_c', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint c'), &
    dataset_spec_t('/timeseries/gears/footpad_joint_force', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'force the footpad puts on the primary at d (the ground force less the footpad''s own '// &
      'inertia), lander axes'), &
    dataset_spec_t('/timeseries/gears/joint_moment_a', 'N m', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'moment joint a puts on the body (along its Hooke-joint axis), lander axes'), &
    dataset_spec_t('/timeseries/gears/joint_moment_b', 'N m', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint b'), &
    dataset_spec_t('/timeseries/gears/joint_moment_c', 'N m', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint c'), &
    dataset_spec_t('/timeseries/gears/gear_axes/joint_force_a', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      '`joint_force_a` in the axes of the gear frame (the lander frame turned by the gear''s '// &
      '`rotation` about z)'), &
    dataset_spec_t('/timeseries/gears/gear_axes/joint_force_b', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint b'), &
    dataset_spec_t('/timeseries/gears/gear_axes/joint_force_c', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint c'), &
    dataset_spec_t('/timeseries/gears/gear_axes/footpad_joint_force', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for the footpad joint d'), &
    dataset_spec_t('/timeseries/gears/gear_axes/joint_moment_a', 'N m', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for the moment of joint a'), &
    dataset_spec_t('/timeseries/gears/gear_axes/joint_moment_b', 'N m', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint b'), &
    dataset_spec_t('/timeseries/gears/gear_axes/joint_moment_c', 'N m', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'same for joint c'), &
    dataset_spec_t('/timeseries/gears/interface_force', 'N', 'n,g,3', 'real', 'x,y,z', '1.2', 'always', &
      'the gear''s total force on the body from the leg''s momentum balance (ground force minus the '// &
      'rate of the legs'' momentum relative to the body, plus the legs'' weight and inertia in the '// &
      'moving frame). Equals `joint_force_a + joint_force_b + joint_force_c` at every sample (the '// &
      'equilibrium check of the regression tests)')]

  !> Datasets of section energy.
  type(dataset_spec_t), parameter :: ds_energy(*) = [ &
    dataset_spec_t('/timeseries/energy/kinetic_body', 'J', 'n', 'real', '', '1.0', 'always', &
      'kinetic energy of the body carrying the total mass (translation of the mass centre and '// &
      'rotation)'), &
    dataset_spec_t('/timeseries/energy/kinetic_legs', 'J', 'n', 'real', '', '1.0', 'always', &
      'the legs'' motion relative to the body: their relative kinetic energy, the cross term v_body '// &
      '* sum m v_rel and the potential energy of their relative displacement. Small; it can be '// &
      'negative.'), &
    dataset_spec_t('/timeseries/energy/potential_released', 'J', 'n', 'real', '', '1.0', 'always', &
      'potential energy released by the body since t = 0'), &
    dataset_spec_t('/timeseries/energy/honeycomb_work', 'J', 'n', 'real', '', '1.0', 'always', &
      'work absorbed by crushing honeycomb, all struts'), &
    dataset_spec_t('/timeseries/energy/contact_damping', 'J', 'n', 'real', '', '1.0', 'always', &
      'work of the normal contact forces dissipated in the ground (total normal work minus '// &
      '`contact_elastic`)'), &
    dataset_spec_t('/timeseries/energy/contact_elastic', 'J', 'n', 'real', '', '1.0', 'always', &
      'elastic energy stored in the footpad-ground contacts at that time'), &
    dataset_spec_t('/timeseries/energy/friction', 'J', 'n', 'real', '', '1.0', 'always', &
      'energy dissipated by footpad friction'), &
    dataset_spec_t('/timeseries/energy/strut_impacts', 'J', 'n', 'real', '', '1.0', 'always', &
      'kinetic energy dissipated when a strut locks or a free strut meets a rigid stop (plastic '// &
      'impacts in Step 4''s correction; the body receives the reaction impulse)'), &
    dataset_spec_t('/timeseries/energy/thrust_work', 'J', 'n', 'real', '', '1.0', 'always', &
      'work of the engine thrust'), &
    dataset_spec_t('/timeseries/energy/input', 'J', 'n', 'real', '', '1.0', 'always', &
      'energy put in so far (see above)'), &
    dataset_spec_t('/timeseries/energy/residual', 'J', 'n', 'real', '', '1.0', 'always', &
      'audit residual (see above)')]

  !> Datasets of section summary.
  type(dataset_spec_t), parameter :: ds_summary(*) = [ &
    dataset_spec_t('/summary/crush_length', 'm', 'g,s', 'real', 's', '1.0', 'always', &
      'signed net crush length per strut, Table 3 sense: `crushed_positive - crushed_negative`. '// &
      'Table 3''s negative values (LC-3) are secondaries crushed in shortening.'), &
    dataset_spec_t('/summary/crushed_positive', 'm', 'g,s', 'real', 's', '1.0', 'always', &
      'honeycomb crushed toward + (primary shortening, secondary lengthening): the largest stroke '// &
      'reached'), &
    dataset_spec_t('/summary/crushed_negative', 'm', 'g,s', 'real', 's', '1.0', 'always', &
      'honeycomb crushed toward - (secondary shortening), as a positive length; 0 for primaries'), &
    dataset_spec_t('/summary/stroke_final', 'm', 'g,s', 'real', 's', '1.0', 'always', &
      'stroke at the end'), &
    dataset_spec_t('/summary/stroke_margin', 'm', 'g,s', 'real', 's', '1.0', 'always', &
      'stroke capacity minus crushed length in the worse direction; negative = bottomed out'), &
    dataset_spec_t('/summary/bottomed_out', '-', 'g,s', 'int', 's', '1.0', 'always', &
      'int 1 where a stroke exceeded its capacity, else 0'), &
    dataset_spec_t('/summary/crush_work', 'J', 'g,s', 'real', 's', '1.0', 'always', &
      'honeycomb crush work per strut'), &
    dataset_spec_t('/summary/mode_switches', '-', 'g,s', 'int', 's', '1.0', 'always', &
      'int number of crush-mode changes per strut over the run (modes: locked, crushing toward +, '// &
      'crushing toward -, sliding freely inside the crushed range)'), &
    dataset_spec_t('/summary/peak_strut_force', 'N', 'g,s', 'real', 's', '1.0', 'always', &
      'largest |axial force| at the output samples'), &
    dataset_spec_t('/summary/peak_overload', 'g', '', 'real', '', '1.0', 'always', &
      'largest |overload| at the mass centre, every time step'), &
    dataset_spec_t('/summary/time_of_peak_overload', 's', '', 'real', '', '1.0', 'always', &
      'its time'), &
    dataset_spec_t('/summary/peak_penetration', 'm', 'g', 'real', '', '1.0', 'always', &
      'largest penetration per footpad, every time step'), &
    dataset_spec_t('/summary/slide_distance', 'm', 'g', 'real', '', '1.0', 'always', &
      'path length of each footpad along its surface while in contact, every time step'), &
    dataset_spec_t('/summary/peak_normal_force', 'N', 'g', 'real', '', '1.0', 'always', &
      'largest normal force per footpad, every time step'), &
    dataset_spec_t('/summary/final_attitude', 'deg', '3', 'real', 'yaw,pitch,roll', '1.0', 'always', &
      'Z-Y-X Euler angles yaw, pitch, roll at the end'), &
    dataset_spec_t('/summary/final_tilt', 'deg', '', 'real', '', '1.0', 'always', &
      'angle between the lander z axis and the vertical at the end'), &
    dataset_spec_t('/summary/max_tilt', 'deg', '', 'real', '', '1.0', 'always', &
      'largest tilt during the run'), &
    dataset_spec_t('/summary/tipped_over', '-', '', 'bool', '', '1.0', 'always', &
      'logical: the tilt exceeded `&simulation tipover_angle` (the run stops there)'), &
    dataset_spec_t('/summary/at_rest', '-', '', 'bool', '', '1.0', 'always', &
      'logical: the lander came to rest (every speed below `rest_speed` for `rest_time`; see '// &
      '[Outcome](#outcome))'), &
    dataset_spec_t('/summary/end_reason', '-', '', 'text', '', '1.0', 'always', &
      'text: `end time reached`, `at rest` or `tipped over`; through the C API also `stopped by '// &
      'the caller at t = <t> s` (a file written before the run reached its end: the outcome is '// &
      'then `still_moving`, inconclusive) or `simulation failed`'), &
    dataset_spec_t('/summary/energy_input', 'J', '', 'real', '', '1.0', 'always', &
      'initial kinetic energy + potential energy released + thrust work, at the end'), &
    dataset_spec_t('/summary/energy_residual', '-', '', 'real', '', '1.0', 'always', &
      'final audit residual / `energy_input`')]

  !> Datasets of section energy_audit.
  type(dataset_spec_t), parameter :: ds_energy_audit(*) = [ &
    dataset_spec_t('/summary/energy_audit/kinetic_body', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/kinetic_body`'), &
    dataset_spec_t('/summary/energy_audit/kinetic_legs', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/kinetic_legs`'), &
    dataset_spec_t('/summary/energy_audit/potential_released', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/potential_released`'), &
    dataset_spec_t('/summary/energy_audit/honeycomb_work', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/honeycomb_work`'), &
    dataset_spec_t('/summary/energy_audit/contact_damping', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/contact_damping`'), &
    dataset_spec_t('/summary/energy_audit/contact_elastic', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/contact_elastic`'), &
    dataset_spec_t('/summary/energy_audit/friction', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/friction`'), &
    dataset_spec_t('/summary/energy_audit/strut_impacts', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/strut_impacts`'), &
    dataset_spec_t('/summary/energy_audit/thrust_work', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/thrust_work`'), &
    dataset_spec_t('/summary/energy_audit/input', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/input`'), &
    dataset_spec_t('/summary/energy_audit/residual', 'J', '', 'real', '', '1.0', 'always', &
      'final value of `/timeseries/energy/residual`')]

  !> Datasets of section summary_run.
  type(dataset_spec_t), parameter :: ds_summary_run(*) = [ &
    dataset_spec_t('/summary/max_constraint_violation', 'm', '', 'real', '', '1.0', 'always', &
      'largest constraint violation after the correction'), &
    dataset_spec_t('/summary/max_constraint_drift', 'm', '', 'real', '', '1.0', 'always', &
      'largest violation before the correction (one step of drift)'), &
    dataset_spec_t('/summary/final_time', 's', '', 'real', '', '1.0', 'always', &
      'time at the end of the run'), &
    dataset_spec_t('/summary/n_steps', '-', '', 'int', '', '1.0', 'always', &
      'int, accepted time steps'), &
    dataset_spec_t('/summary/integrator/name', '-', '', 'text', '', '1.0', 'always', &
      'string, `fixed` or `adaptive`'), &
    dataset_spec_t('/summary/integrator/n_evaluations', '-', '', 'int', '', '1.0', 'always', &
      'int, force evaluations, rejected steps included (the cost)'), &
    dataset_spec_t('/summary/integrator/n_rejected', '-', '', 'int', '', '1.0', 'always', &
      'int, rejected steps (local error above the tolerance, an event to locate, a failed '// &
      'correction); 0 for `fixed`'), &
    dataset_spec_t('/summary/integrator/n_events', '-', '', 'int', '', '1.0', 'always', &
      'int, accepted steps that ended at a located event'), &
    dataset_spec_t('/summary/integrator/n_forced', '-', '', 'int', '', '1.0', 'always', &
      'int, steps of `event_resolution` accepted with the local error estimate above the tolerance '// &
      '(discontinuities crossed)'), &
    dataset_spec_t('/summary/integrator/n_releases', '-', '', 'int', '', '1.3', 'always', &
      'int, strut releases (a locked strut that crushes or slides freely at the next accepted '// &
      'step), all struts (schema 1.3)'), &
    dataset_spec_t('/summary/integrator/n_releases_after_lock', '-', '', 'int', '', '1.3', 'always', &
      'int, of those, releases in the accepted step after one in which a strut locked '// &
      '(docs/theory.md, "Mode switches") (schema 1.3)'), &
    dataset_spec_t('/summary/integrator/dt_smallest', 's', '', 'real', '', '1.0', 'always', &
      'smallest accepted step'), &
    dataset_spec_t('/summary/integrator/dt_largest', 's', '', 'real', '', '1.0', 'always', &
      'largest accepted step'), &
    dataset_spec_t('/summary/wall_time', 's', '', 'real', '', '1.0', 'always', &
      'wall-clock time of the simulation')]

  !> Datasets of section peak_loads.
  type(dataset_spec_t), parameter :: ds_peak_loads(*) = [ &
    dataset_spec_t('/summary/peak_joint_load/value', 'N', 'g,4,4', 'real', '', '1.2', 'always', &
      'peak per gear, joint (a, b, c, d), quantity (x, y, z, magnitude): the component of largest '// &
      'absolute value, signed; the magnitude >= 0'), &
    dataset_spec_t('/summary/peak_joint_load/time', 's', 'g,4,4', 'real', '', '1.2', 'always', &
      'instant of each peak'), &
    dataset_spec_t('/summary/peak_joint_load/simultaneous', 'N, N m', 'g,16,21', 'real', '', '1.2', 'always', &
      'the gear''s 21 loads at the instant of each peak; row 4 x joint + quantity (0-based), '// &
      'columns `load_names`'), &
    dataset_spec_t('/summary/peak_joint_load/load_names', '-', '21', 'text', '', '1.2', 'always', &
      '`Fa_x Fa_y Fa_z Fb_x ... Fd_z` (forces of a, b, c on the body and of the footpad on the '// &
      'primary at d, N), `Ma_x ... Mc_z` (moments of a, b, c on the body, N m)'), &
    dataset_spec_t('/summary/peak_joint_load/joint_names', '-', '4', 'text', '', '1.2', 'always', &
      '`a b c d`'), &
    dataset_spec_t('/summary/peak_joint_load/quantity_names', '-', '4', 'text', '', '1.2', 'always', &
      '`x y z magnitude`')]

  !> Datasets of section health.
  type(dataset_spec_t), parameter :: ds_health(*) = [ &
    dataset_spec_t('/summary/health/status', '-', '', 'int', '', '1.0', 'with health', &
      'worst check: 0 all passed, 1 warnings (result doubtful), 2 failed (result physically '// &
      'meaningless; `landyn` exits 6)'), &
    dataset_spec_t('/summary/health/checks', '-', '6', 'text', '', '1.0', 'with health', &
      'names of the checks: `leg_mass`, `gear_separation`, `initial_penetration`, `strut_length`, '// &
      '`energy_residual`, `finite_peaks`'), &
    dataset_spec_t('/summary/health/results', '-', '6', 'int', '', '1.0', 'with health', &
      'per check, in the order of `checks`: 0 passed, 1 warning, 2 failed'), &
    dataset_spec_t('/summary/health/messages', '-', '', 'text', '', '1.0', 'with health', &
      'one line per check that did not pass (`FAILED` or `warning`, the check, what was found and '// &
      'the threshold); `none` when all passed')]

  !> Datasets of section outcome.
  type(dataset_spec_t), parameter :: ds_outcome(*) = [ &
    dataset_spec_t('/summary/outcome/code', '-', '', 'int', '', '1.3', 'always', &
      'the class above (0 `none`: not classified)'), &
    dataset_spec_t('/summary/outcome/name', '-', '', 'text', '', '1.3', 'always', &
      'its name'), &
    dataset_spec_t('/summary/outcome/touched_down', '-', '', 'bool', '', '1.3', 'always', &
      'logical: a footpad touched the ground'), &
    dataset_spec_t('/summary/outcome/body_speed', 'm/s', '', 'real', '', '1.3', 'always', &
      'mass-centre speed at the final time'), &
    dataset_spec_t('/summary/outcome/angular_rate', 'deg/s', '', 'real', '', '1.3', 'always', &
      '|omega| at the final time'), &
    dataset_spec_t('/summary/outcome/slide_rate', 'm/s', '', 'real', '', '1.3', 'always', &
      'largest footpad speed along its terrain plane at the final time'), &
    dataset_spec_t('/summary/outcome/footpad_speed', 'm/s', '', 'real', '', '1.3', 'always', &
      'largest footpad speed (slide and sink) at the final time'), &
    dataset_spec_t('/summary/outcome/stroke_rate', 'm/s', '', 'real', '', '1.3', 'always', &
      'largest strut stroke rate at the final time'), &
    dataset_spec_t('/summary/outcome/tipover_margin', 'deg', '', 'real', '', '1.3', 'always', &
      'the **tip-over margin** of the final state: the support polygon is the convex hull of the '// &
      'footpads in contact, seen along gravity; about each of its edges (the 3D line through two '// &
      'footpads) the angle the lander must still turn until the gravity line through the mass '// &
      'centre meets the edge; the smallest. Positive: stable; <= 0: not statically stable (fewer '// &
      'than 3 footpads in contact give 0). The body''s mass centre (the legs'' few % are left out)'), &
    dataset_spec_t('/summary/outcome/friction_ratio', '-', 'g', 'real', '', '1.3', 'always', &
      'per footpad, the **static friction ratio** |F_t|/(mu_s F_n) of the final state with mu_s = '// &
      '`&friction mu_static`: below 1 the footpad holds by static friction, 1 or above it slides; '// &
      '0 off the ground')]

  !> Datasets of section api_inputs.
  type(dataset_spec_t), parameter :: ds_api_inputs(*) = [ &
    dataset_spec_t('/api/inputs/time', 's', 'm', 'real', '', '1.0', 'api inputs', &
      'simulation time of the call'), &
    dataset_spec_t('/api/inputs/force', 'N', 'm,3', 'real', 'x,y,z', '1.0', 'api inputs', &
      'force at the `&engine point`, lander axes, added to the deck''s `&engine` thrust'), &
    dataset_spec_t('/api/inputs/moment', 'N m', 'm,3', 'real', 'x,y,z', '1.0', 'api inputs', &
      'pure moment, lander axes')]

  !> Every dataset of a result file, in the order of docs/output.md.
  type(dataset_spec_t), parameter :: output_datasets(*) = [ds_meta, ds_model, ds_body, ds_gears, ds_loads, ds_energy, ds_summary, &
    ds_energy_audit, ds_summary_run, ds_peak_loads, ds_health, ds_outcome, ds_api_inputs]

contains

  !> Index of `path` in output_datasets, 0 when the schema has no such dataset.
  pure integer function find_dataset(path) result(k)
    character(len=*), intent(in) :: path    !! absolute dataset path [-]
    do k = 1, size(output_datasets)
      if (output_datasets(k)%path == path) return
    end do
    k = 0
  end function find_dataset

  !> Rank of a dataset (the number of its shape symbols; 0 for a scalar).
  pure integer function spec_rank(spec) result(r)
    type(dataset_spec_t), intent(in) :: spec  !! dataset [-]
    integer :: i
    r = 0
    if (len_trim(spec%shape) == 0) return
    r = 1
    do i = 1, len_trim(spec%shape)
      if (spec%shape(i:i) == ',') r = r + 1
    end do
  end function spec_rank

end module landyn_output_schema
