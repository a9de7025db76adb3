-- hydrocoef run database, migration 14: the restoring force removed from a
-- forced-oscillation run before its fit (hydrocoef pmm --restoring C).
--
-- restoring: C of F = -C x on the oscillated degree of freedom's own
-- component (N/m for surge, sway, heave; N m/rad for roll, pitch, yaw), a
-- floating body's hydrostatics, in phase with the displacement; it was
-- removed from the force history, and from the kept history, before the
-- added mass was fitted. NULL: none was removed.
ALTER TABLE pmm_run ADD COLUMN restoring REAL;
