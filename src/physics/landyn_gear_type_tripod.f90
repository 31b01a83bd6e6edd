!> The gear type 'tripod' (&gears gear_type): the paper's landing gear (landyn_tripod_gear), one
!! primary strut and two secondary struts, built from the &gears hard points of its gear, the
!! struts' masses of &primary_strut and &secondary_strut, their buffer laws (buffer_law of those
!! groups, made by the buffer-law registry landyn_buffer_laws) and the primary's tube friction.
!! `tripod_parts` gives those parts to a tripod variant's builder, which may change some of them
!! before its own tripod_init.
module landyn_gear_type_tripod
  use landyn_kinds, only: wp, msg_len
  use landyn_kinematics, only: rot_z, build_gear_geometry, gear_geometry_t
  use landyn_status, only: status_t
  use landyn_strut, only: strut_mass_t
  use landyn_tripod_gear, only: tripod_gear_t, tripod_init
  use landyn_buffer, only: buffer_law_t
  use landyn_buffer_laws, only: make_buffer_law
  use landyn_tube_friction, only: tube_friction_t, make_tube_friction
  use landyn_gear_build, only: gear_build_t
  implicit none
  private

  public :: build, tripod_parts, tripod_parts_t

  !> What tripod_init takes, from the input of one gear.
  type :: tripod_parts_t
    type(gear_geometry_t) :: geom                        !! hard points in the gear frame
    real(wp) :: rot(3, 3) = 0.0_wp                       !! gear frame -> lander frame [-]
    type(strut_mass_t) :: sm(3)                          !! strut mass properties (primary, left, right)
    class(buffer_law_t), allocatable :: primary          !! the primary's buffer law
    class(buffer_law_t), allocatable :: secondary        !! the secondaries' buffer law
    type(tube_friction_t) :: tube                        !! the primary's tube friction
  end type tripod_parts_t

contains

  !> The registry's builder of 'tripod' (landyn_gear_types): gear b%i of the input.
  subroutine build(b)
    type(gear_build_t), intent(inout) :: b   !! the build
    type(tripod_parts_t) :: p
    type(tripod_gear_t) :: tripod
    logical :: ok
    type(status_t) :: gst
    if (b%check_only) return
    call tripod_parts(b, p, ok)
    if (.not. ok) return
    call tripod_init(tripod, p%geom, p%rot, p%sm, p%primary, p%secondary, gst, p%tube)
    if (.not. gst%ok()) then; call b%errors%add(gst%text()); return; end if
    allocate (b%gear, source=tripod)
  end subroutine build

  !> The parts of tripod b%i from the input: gear frame and geometry, strut masses, buffer laws
  !! (from their registry) and tube friction. ok = .false. with the problem appended to b%errors.
  subroutine tripod_parts(b, p, ok)
    type(gear_build_t), intent(inout) :: b   !! the build
    type(tripod_parts_t), intent(out) :: p   !! the parts
    logical, intent(out) :: ok               !! all parts made [-]
    real(wp) :: pts(3, 6)
    character(len=msg_len) :: msg
    type(status_t) :: gst

    ok = .false.
    associate (pri => b%inp%primary, sec => b%inp%secondary, g => b%inp%gears, i => b%i)
      call make_tube_friction(pri%tube_friction, pri%mu_tube, pri%tube_outer_length, pri%tube_inner_length, &
                              pri%tube_leg_length, pri%tube_lever, p%tube, gst)
      if (.not. gst%ok()) then; call b%errors%add(gst%text()); return; end if
      call make_buffer_law(pri, sec, .true., p%primary, gst)
      if (.not. gst%ok()) then; call b%errors%add(gst%text()); return; end if
      call make_buffer_law(pri, sec, .false., p%secondary, gst)
      if (.not. gst%ok()) then; call b%errors%add(gst%text()); return; end if
      p%sm(1) = strut_mass_t(pri%outer_mass, pri%outer_cm, pri%outer_inertia, pri%inner_mass, pri%inner_cm, &
                             pri%inner_inertia, pri%footpad_mass)
      p%sm(2) = strut_mass_t(sec%outer_mass, sec%outer_cm, sec%outer_inertia, sec%inner_mass, sec%inner_cm, &
                             sec%inner_inertia, 0.0_wp)
      p%sm(3) = p%sm(2)
      p%rot = rot_z(g%rotation(i))
      pts = reshape([g%point_a(:, i), g%point_b(:, i), g%point_c(:, i), g%point_d(:, i), g%point_e(:, i), &
                     g%point_f(:, i)], [3, 6])
      pts = matmul(transpose(p%rot), pts)          ! lander frame -> gear frame
      call build_gear_geometry(pts(:, 1), pts(:, 2), pts(:, 3), pts(:, 4), pts(:, 5), pts(:, 6), p%geom, gst)
      if (.not. gst%ok()) then
        write (msg, '(a,i0,a,a)') '&gears: gear ', i, ': ', gst%text()
        call b%errors%add(trim(msg))
        return
      end if
    end associate
    ok = .true.
  end subroutine tripod_parts

end module landyn_gear_type_tripod
