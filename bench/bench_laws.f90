!> Benchmark of the interchangeable laws (issue 4, item 6): the time-step-loop cost of LC-1 with
!! each contact law and each friction law (and the tube friction) relative to the base laws.
!!
!!   bench_laws LC1_DECK [runs] [limit_percent]
!!
!! Two figures per law:
!!  * loop: best-of-`runs` wall time of the whole LC-1 run (setup is negligible) per time step,
!!    relative to the base laws. This includes the law's effect on the landing itself (a law that
!!    changes the crush events changes how long the gears stay on their rigid fast path), so it
!!    can move either way by more than the law's own cost;
!!  * law: the law's own cost per time step (n_gears footpad evaluations, measured on a recorded
!!    sequence of footpad states, dispatch included) minus the base law's, relative to the base
!!    run's cost per step. This is the cost of choosing the law, the target being <= 10 %.
!! Exit status 1 when a law's own extra cost exceeds limit_percent (default 10).
program bench_laws
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_input, only: input_errors_t, load_input
  use landyn_simulation, only: sim_result_t, run_simulation
  use landyn_contact, only: contact_law_t, make_contact_law, contact_state_t, advance_contact_state
  use landyn_friction, only: friction_law_t, make_friction_law, friction_state_t
  implicit none

  integer, parameter :: n_contact = 8, n_friction = 8, n_samples = 400000
  character(len=24), parameter :: contact_laws(n_contact) = [character(len=24) :: 'base', 'adams_impact', 'hertz', &
    'kelvin_voigt', 'kelvin_voigt_step', 'kelvin_voigt_bilinear', 'hunt_crossley', 'regolith']
  character(len=24), parameter :: friction_laws(n_friction) = [character(len=24) :: 'coulomb_step', 'adams_step', &
    'ty1', 'ty2', 'ty3', 'ty4', 'ty5', 'ty6']
  type(landyn_input_t) :: base_inp, inp
  type(input_errors_t) :: errors
  character(len=1024) :: deck, arg
  integer :: runs, stat, i, worst_status
  real(wp) :: limit, base_step, t_loop, t_law, t_law_base, delta(n_samples), delta_dot(n_samples)
  real(wp) :: vslip(2, n_samples), fn(n_samples)
  integer :: n_gears

  if (command_argument_count() < 1) then
    write (error_unit, '(a)') 'usage: bench_laws LC1_DECK [runs] [limit_percent]'
    stop 1
  end if
  call get_command_argument(1, deck)
  runs = 3
  limit = 10.0_wp
  if (command_argument_count() >= 2) then
    call get_command_argument(2, arg)
    read (arg, *) runs
  end if
  if (command_argument_count() >= 3) then
    call get_command_argument(3, arg)
    read (arg, *) limit
  end if
  call load_input(trim(deck), base_inp, errors, stat)
  if (stat /= 0) then
    call errors%write(error_unit)
    stop 2
  end if
  n_gears = base_inp%gears%n_gears
  call footpad_samples(delta, delta_dot, vslip, fn)

  write (output_unit, '(a,i0,a,es9.2,a)') 'bench_laws: LC-1, best of ', runs, ' runs, dt = ', base_inp%simulation%dt, ' s'
  base_step = loop_cost(base_inp)
  write (output_unit, '(a,f8.3,a)') '  base laws (base, coulomb_step): ', 1.0e6_wp*base_step, ' us per time step'
  worst_status = 0

  write (output_unit, '(a)') ''
  write (output_unit, '(a)') '  contact law              loop [us/step]  loop vs base [%]  law [ns/footpad]  law vs base [%]'
  t_law_base = contact_cost('base')
  do i = 1, n_contact
    inp = base_inp
    inp%contact%law = contact_laws(i)
    t_loop = loop_cost(inp)
    t_law = contact_cost(trim(contact_laws(i)))
    call report(contact_laws(i), t_loop, t_law, t_law_base)
  end do

  write (output_unit, '(a)') ''
  write (output_unit, '(a)') '  friction law             loop [us/step]  loop vs base [%]  law [ns/footpad]  law vs base [%]'
  t_law_base = friction_cost('coulomb_step')
  do i = 1, n_friction
    inp = base_inp
    inp%friction%law = friction_laws(i)
    t_loop = loop_cost(inp)
    t_law = friction_cost(trim(friction_laws(i)))
    call report(friction_laws(i), t_loop, t_law, t_law_base)
  end do

  write (output_unit, '(a)') ''
  inp = base_inp
  inp%primary%tube_friction = .true.
  t_loop = loop_cost(inp)
  write (output_unit, '(a,f16.3,f18.1)') '  tube friction on       ', 1.0e6_wp*t_loop, 100.0_wp*(t_loop/base_step - 1.0_wp)
  if (worst_status /= 0) then
    write (output_unit, '(a,f5.1,a)') 'bench_laws: a law costs more than ', limit, ' % of the base loop'
    stop 1
  end if
  write (output_unit, '(a,f5.1,a)') 'bench_laws: every law costs the loop less than ', limit, ' %'

contains

  !> Best-of-runs wall time per time step of a whole run [s].
  function loop_cost(run_inp) result(per_step)
    type(landyn_input_t), intent(in) :: run_inp   !! input
    real(wp) :: per_step                          !! [s]
    type(sim_result_t) :: res
    integer :: k, st
    character(len=512) :: msg
    per_step = huge(1.0_wp)
    do k = 1, runs
      call run_simulation(run_inp, res, st, msg, -1)
      if (st /= 0) then
        write (error_unit, '(a)') 'bench_laws: run failed: '//trim(msg)
        stop 3
      end if
      per_step = min(per_step, res%wall_time/real(max(res%n_steps, 1), wp))
    end do
  end function loop_cost

  !> Footpad states as the time loop sees them: a touchdown-like penetration history [m, m/s],
  !! slip velocities [m/s] and normal forces [N].
  subroutine footpad_samples(d, dd, vs, f)
    real(wp), intent(out) :: d(:)       !! penetrations [m]
    real(wp), intent(out) :: dd(:)      !! penetration rates [m/s]
    real(wp), intent(out) :: vs(:, :)   !! slip velocities [m/s]
    real(wp), intent(out) :: f(:)       !! normal forces [N]
    integer :: k
    real(wp) :: t
    do k = 1, size(d)
      t = real(k, wp)/real(size(d), wp)
      d(k) = 1.0e-3_wp*sin(37.0_wp*t)**2 - 1.0e-5_wp
      dd(k) = 0.5_wp*cos(53.0_wp*t)
      vs(:, k) = [0.3_wp*sin(11.0_wp*t), 0.05_wp*cos(7.0_wp*t)]
      f(k) = max(0.0_wp, 8.0e4_wp*sin(29.0_wp*t))
    end do
  end subroutine footpad_samples

  !> Cost of one footpad's contact evaluation as in the loop (update for laws with history) [s].
  function contact_cost(name) result(per_call)
    character(len=*), intent(in) :: name      !! law name
    real(wp) :: per_call                      !! [s]
    class(contact_law_t), allocatable :: law
    type(contact_state_t) :: cst
    type(landyn_input_t) :: tmp
    integer :: k, st, rep
    integer(int64) :: c0, c1, rate
    real(wp) :: acc
    character(len=256) :: msg
    tmp = base_inp
    tmp%contact%law = name
    call make_contact_law(tmp%contact, law, st, msg)
    per_call = huge(1.0_wp)
    acc = 0.0_wp
    do rep = 1, 5
      call system_clock(c0, rate)
      do k = 1, n_samples
        if (law%has_history) call advance_contact_state(cst, delta(k), delta_dot(k))
        if (delta(k) > 0.0_wp) acc = acc + law%normal_force(delta(k), delta_dot(k), cst)
      end do
      call system_clock(c1)
      per_call = min(per_call, real(c1 - c0, wp)/real(rate, wp)/real(n_samples, wp))
    end do
    if (acc < 0.0_wp) write (output_unit, '(a)') 'impossible'   ! keeps the loop
  end function contact_cost

  !> Cost of one footpad's friction evaluation as in the loop (stick_slip_force for stiction laws) [s].
  function friction_cost(name) result(per_call)
    character(len=*), intent(in) :: name      !! law name
    real(wp) :: per_call                      !! [s]
    class(friction_law_t), allocatable :: law
    type(friction_state_t) :: fst
    type(landyn_input_t) :: tmp
    integer :: k, st, rep
    integer(int64) :: c0, c1, rate
    real(wp) :: acc, ft(2)
    character(len=256) :: msg
    tmp = base_inp
    tmp%friction%law = name
    tmp%friction%stribeck_speed = 1.0_wp
    call make_friction_law(tmp%friction, law, st, msg)
    per_call = huge(1.0_wp)
    acc = 0.0_wp
    do rep = 1, 5
      call system_clock(c0, rate)
      do k = 1, n_samples
        if (law%has_stiction) then
          call law%stick_slip_force(fst, vslip(:, k), 5.0e-6_wp*vslip(:, k), 5.0e-6_wp, fn(k), ft)
        else
          ft = law%friction_force(vslip(:, k), fn(k))
        end if
        acc = acc + ft(1)
      end do
      call system_clock(c1)
      per_call = min(per_call, real(c1 - c0, wp)/real(rate, wp)/real(n_samples, wp))
    end do
    if (acc > huge(1.0_wp)) write (output_unit, '(a)') 'impossible'   ! keeps the loop
  end function friction_cost

  subroutine report(name, loop, law, law_base)
    character(len=*), intent(in) :: name      !! law name
    real(wp), intent(in) :: loop              !! loop cost per step [s]
    real(wp), intent(in) :: law               !! law cost per footpad evaluation [s]
    real(wp), intent(in) :: law_base          !! base law cost per footpad evaluation [s]
    real(wp) :: extra
    extra = 100.0_wp*real(n_gears, wp)*(law - law_base)/base_step
    write (output_unit, '(2x,a24,f15.3,f18.1,f18.1,f17.2)') name, 1.0e6_wp*loop, 100.0_wp*(loop/base_step - 1.0_wp), &
      1.0e9_wp*law, extra
    if (extra > limit) worst_status = 1
  end subroutine report

end program bench_laws
