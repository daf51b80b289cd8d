package net.smc.sim.team;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import net.smc.sim.hardware.Battery;
import net.smc.sim.hardware.Camera;
import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.ControlLoop;
import net.smc.sim.hardware.Drive;
import net.smc.sim.hardware.Odometry;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;
import net.smc.sim.hardware.Radio;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.world.Arena;
import net.smc.sim.world.SimWorld;

/**
 * The hardware of a station (the commander's laptop, the soldier's wearable computer): it knows
 * where it stands and has a radio, nothing else. Tasks that need only a position and a control
 * period (the Beacon) run on it; its control loops run once per world step.
 */
final class StationHardware implements RobotHardware {
    private final Arena.Station station;
    private final String id;
    private final Radio radio;
    private final Map<Object, ControlLoop> loops = new LinkedHashMap<>();

    StationHardware(String vehicleId, Arena.Station station, SimWorld world) {
        this.id = Objects.requireNonNull(vehicleId, "vehicleId");
        this.station = Objects.requireNonNull(station, "station");
        this.radio = world.radio().view(station.id());
    }

    /** Runs the control loops: called once per world step with the mission time, seconds. */
    void step(double time, double dt) {
        for (ControlLoop loop : List.copyOf(loops.values())) {
            loop.step(time, dt);
        }
    }

    @Override
    public String id() {
        return id;
    }

    @Override
    public boolean has(Device device) {
        return device == Device.ODOMETRY || device == Device.RADIO;
    }

    @Override
    public Drive drive() {
        return new Drive() {
            @Override
            public void setWheelSpeeds(double left, double right) {
                // a station does not move
            }

            @Override
            public double maxSpeed() {
                return 0;
            }

            @Override
            public double wheelBase() {
                return 0;
            }

            @Override
            public boolean working() {
                return false;
            }
        };
    }

    @Override
    public Odometry odometry() {
        return new Odometry() {
            @Override
            public Pose pose() {
                return new Pose(station.x(), station.y(), 0);
            }

            @Override
            public double travelled() {
                return 0;
            }
        };
    }

    @Override
    public ProximitySensors proximity() {
        return new ProximitySensors() {
            @Override
            public int count() {
                return 0;
            }

            @Override
            public double angle(int i) {
                throw new IndexOutOfBoundsException("a station has no proximity sensors");
            }

            @Override
            public double range() {
                return 0;
            }

            @Override
            public double[] read() {
                return new double[0];
            }
        };
    }

    @Override
    public Camera camera() {
        return new Camera() {
            @Override
            public double fieldOfView() {
                return 0;
            }

            @Override
            public double range() {
                return 0;
            }

            @Override
            public List<net.smc.sim.hardware.Sighting> look() {
                return List.of();
            }
        };
    }

    @Override
    public ChemicalSensor chemical() {
        return new ChemicalSensor() {
            @Override
            public double radius() {
                return 0;
            }

            @Override
            public List<Reading> sense() {
                return List.of();
            }
        };
    }

    @Override
    public Battery battery() {
        return () -> 1.0;
    }

    @Override
    public Radio radio() {
        return radio;
    }

    @Override
    public void control(Object owner, ControlLoop loop) {
        if (loop == null) {
            loops.remove(owner);
        } else {
            loops.put(owner, loop);
        }
    }

    @Override
    public String toString() {
        return "station " + station.id() + " (" + id + ")";
    }

}
